package sitcov.vehicles;

import sitcov.world.Target;

/**
 * Whether the car stands on the Target, judged by the world from geometry: its front centre within
 * {@value #CAPTURE_DISTANCE} m of the Target, which may lie anywhere across its road
 * (experiments/controllers/README.md, "What the oracle judges"). The builtin car used to end the run itself, once it
 * also believed the Target
 * to be in its lane; the world cannot take a controller's word for that.
 */
public final class TargetArrival {
    public static final double CAPTURE_DISTANCE = 1.5;

    private Target target;

    TargetArrival(Target target) {
        this.target = target;
    }

    boolean isReached(double x, double y) {
        return target.position().distanceTo(x, y) < CAPTURE_DISTANCE;
    }
}
