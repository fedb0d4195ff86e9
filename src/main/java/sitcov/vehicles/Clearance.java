package sitcov.vehicles;

import sitcov.geom.Bearing;
import sitcov.geom.Box;

/** The check a moving car makes before each move, so that traffic keeps clear of everyone. */
final class Clearance {
    /** Room kept round the autonomous car: traffic never touches it. */
    static final double AROUND_THE_CAR = 0.3;
    /** Anything whose anchor is further than this (squared, metres) is not looked at. */
    private static final double NEAR_SQ = 12 * 12;

    private Clearance() {
    }

    /**
     * Whether the footprint {@code next} of {@code self} would touch another vehicle or a parked
     * car that it does not touch already (a car already entangled may move off), or come within
     * {@link #AROUND_THE_CAR} of the autonomous car.
     */
    static boolean wouldTouch(Scene scene, Vehicle self, Box next) {
        Box now = null;
        for (Vehicle other : scene.vehicles()) {
            if (other == self || !other.isActive() || isFar(self, other.x(), other.y())) {
                continue;
            }
            Box theirs = other.id() == AutonomousCar.ID
                    ? Box.behind(other.x() + AROUND_THE_CAR * Bearing.dx(other.heading()),
                            other.y() + AROUND_THE_CAR * Bearing.dy(other.heading()), other.heading(),
                            other.length() + 2 * AROUND_THE_CAR, other.width() + 2 * AROUND_THE_CAR)
                    : other.footprint();
            if (next.overlaps(theirs)) {
                now = now == null ? self.footprint() : now;
                if (!now.overlaps(theirs)) {
                    return true;
                }
            }
        }
        for (Box parked : scene.parkedBodies()) {
            if (!isFar(self, parked.centre().x(), parked.centre().y()) && next.overlaps(parked)) {
                now = now == null ? self.footprint() : now;
                if (!now.overlaps(parked)) {
                    return true;
                }
            }
        }
        return false;
    }

    private static boolean isFar(Vehicle self, double ox, double oy) {
        double dx = ox - self.x();
        double dy = oy - self.y();
        return dx * dx + dy * dy > NEAR_SQ;
    }
}
