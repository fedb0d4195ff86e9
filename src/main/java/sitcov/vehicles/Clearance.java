package sitcov.vehicles;

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
        for (int each = 0, count = scene.vehicles().size(); each < count; each++) {
            Vehicle other = scene.vehicles().get(each);
            if (other == self || !other.isActive() || isFar(self, other.x(), other.y())) {
                continue;
            }
            Box theirs = other instanceof AutonomousCar car ? car.keptClear() : other.footprint();
            if (next.overlaps(theirs)) {
                now = now == null ? self.footprint() : now;
                if (!now.overlaps(theirs)) {
                    return true;
                }
            }
        }
        for (int each = 0, count = scene.parkedBodies().size(); each < count; each++) {
            Box parked = scene.parkedBodies().get(each);
            if (!isFar(self, parked.centreX(), parked.centreY()) && next.overlaps(parked)) {
                now = now == null ? self.footprint() : now;
                if (!now.overlaps(parked)) {
                    return true;
                }
            }
        }
        return false;
    }

    /** Whether anything {@link #wouldTouch} looks at is near: most ticks nothing is, and the reach need not be built. */
    static boolean anyoneNear(Scene scene, Vehicle self) {
        for (int each = 0, count = scene.vehicles().size(); each < count; each++) {
            Vehicle other = scene.vehicles().get(each);
            if (other != self && other.isActive() && !isFar(self, other.x(), other.y())) {
                return true;
            }
        }
        for (int each = 0, count = scene.parkedBodies().size(); each < count; each++) {
            Box parked = scene.parkedBodies().get(each);
            if (!isFar(self, parked.centreX(), parked.centreY())) {
                return true;
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
