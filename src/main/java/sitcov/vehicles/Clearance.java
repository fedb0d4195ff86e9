package sitcov.vehicles;

import sitcov.control.Vehicle;
import sitcov.geom.Box;

/**
 * The check a moving car makes before each move, so that traffic keeps clear of everyone. One per
 * car: it remembers who was near when last asked, so the check itself looks only at them.
 */
final class Clearance {
    /** Room kept round the autonomous car: traffic never touches it. */
    static final double AROUND_THE_CAR = 0.3;
    /** Anything whose anchor is further than this (squared, metres) is not looked at. */
    private static final double NEAR_SQ = 12 * 12;

    /** Who is near, in scene order: the vehicles {@link #vehicleAt} noted, the parked cars {@link #anyoneNear} found. */
    private int[] nearVehicles = new int[16];
    private int[] nearParked = new int[16];
    private int vehiclesNear;
    private int parkedNear;

    /** Starts a step's list of the vehicles near the car (its pass over the traffic fills it). */
    void clearNear() {
        vehiclesNear = 0;
    }

    /**
     * The active vehicle at scene index {@code index}, not the car itself, lies {@code distanceSq}
     * (squared metres, anchor to anchor) from it: noted if near. Called in scene order.
     */
    void vehicleAt(int index, double distanceSq) {
        if (!(distanceSq > NEAR_SQ)) {
            nearVehicles = add(nearVehicles, vehiclesNear++, index);
        }
    }

    /**
     * Whether anything {@link #wouldTouch} looks at is near — the vehicles noted since
     * {@link #clearNear}, nobody having moved since, and the parked cars: most ticks nothing is,
     * and the reach need not be built. Remembers who is, for {@link #wouldTouch} to ask next.
     */
    boolean anyoneNear(Scene scene, Vehicle self) {
        parkedNear = 0;
        for (int each = 0, count = scene.parkedBodies().size(); each < count; each++) {
            Box parked = scene.parkedBodies().get(each);
            if (!isFar(self, parked.centreX(), parked.centreY())) {
                nearParked = add(nearParked, parkedNear++, each);
            }
        }
        return vehiclesNear + parkedNear > 0;
    }

    /**
     * Whether the footprint {@code next} of {@code self} would touch another vehicle or a parked
     * car near it (as {@link #anyoneNear} just found, nobody having moved since) that it does not
     * touch already (a car already entangled may move off), or come within
     * {@link #AROUND_THE_CAR} of the autonomous car.
     */
    boolean wouldTouch(Scene scene, Vehicle self, Box next) {
        Box now = null;
        for (int k = 0; k < vehiclesNear; k++) {
            Vehicle other = scene.vehicleArray()[nearVehicles[k]];
            Box theirs = other instanceof AutonomousCar car ? car.keptClear() : other.footprint();
            if (next.overlaps(theirs)) {
                now = now == null ? self.footprint() : now;
                if (!now.overlaps(theirs)) {
                    return true;
                }
            }
        }
        for (int k = 0; k < parkedNear; k++) {
            Box parked = scene.parkedBodies().get(nearParked[k]);
            if (next.overlaps(parked)) {
                now = now == null ? self.footprint() : now;
                if (!now.overlaps(parked)) {
                    return true;
                }
            }
        }
        return false;
    }

    private static int[] add(int[] list, int at, int index) {
        int[] into = at < list.length ? list : java.util.Arrays.copyOf(list, 2 * list.length);
        into[at] = index;
        return into;
    }

    private static boolean isFar(Vehicle self, double ox, double oy) {
        double dx = ox - self.x();
        double dy = oy - self.y();
        return dx * dx + dy * dy > NEAR_SQ;
    }
}
