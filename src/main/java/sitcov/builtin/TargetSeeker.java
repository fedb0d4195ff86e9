package sitcov.builtin;

import sitcov.faults.Fault;
import sitcov.faults.FaultSwitchboard;
import sitcov.geom.Bearing;
import sitcov.geom.Compass;
import sitcov.sensors.LaneEstimate;
import sitcov.vehicles.TargetArrival;
import sitcov.world.Target;

/**
 * Reaching the Target: once it is a short way ahead and in the car's own lane (judged from the
 * markings the camera sees), the car steers towards it, keeping its body in the lane, and stops
 * on it. It counts as reached within 1.5 m, in the car's own lane.
 */
final class TargetSeeker {
    static final double CAPTURE_DISTANCE = TargetArrival.CAPTURE_DISTANCE;
    static final double SEEK_DISTANCE = 15;
    static final double DIRECT_DISTANCE = 4.5;
    /** How far the car's front centre may move off its lane centre and keep its body in the lane. */
    static final double LATERAL_FREEDOM = 0.45;
    /** A Target further than this to the side of the car cannot be reached without changing lane. */
    static final double REACHABLE_ASIDE = 1.4;

    private BuiltinCar car;
    private FaultSwitchboard faults;

    TargetSeeker(BuiltinCar car, FaultSwitchboard faults) {
        this.car = car;
        this.faults = faults;
    }

    void plan(Intent intent, Compass lane, LaneEstimate estimate) {
        Target target = car.target();
        double u = LaneFrame.u(lane, car.x(), car.y(), target.position().x(), target.position().y());
        double v = LaneFrame.v(lane, car.x(), car.y(), target.position().x(), target.position().y());
        if (u < 0 || u > SEEK_DISTANCE) {
            // a Target passed without reaching it (it lay too far to the side) is not stood beside
            // for ever: the car drives on and comes round again
            return;
        }
        // turning through a junction the lane frame means little, and passing parked cars the car
        // is out in the other lane: it heads for the Target only once it can reach it from its lane
        if (car.isCrossingJunction() || (car.overtakingStage().isPassing() && Math.abs(v) > REACHABLE_ASIDE)) {
            return;
        }
        double laneCentre = estimate.laneCentre();
        if (!inLane(v, laneCentre)) {
            if (u <= DIRECT_DISTANCE && faults.watches(Fault.TARGET_LANE_CHECK_SKIPPED)) {
                faults.effective(Fault.TARGET_LANE_CHECK_SKIPPED);
            }
            if (u <= DIRECT_DISTANCE && faults.isActive(Fault.TARGET_LANE_CHECK_SKIPPED)) {
                intent.stopWithin(Math.max(0, u), "target");
                intent.steer(Bearing.between(car.x(), car.y(), target.position().x(), target.position().y()), "target");
            }
            return;
        }
        if (u <= DIRECT_DISTANCE && faults.watches(Fault.TARGET_LANE_CHECK_SKIPPED)) {
            faults.reached(Fault.TARGET_LANE_CHECK_SKIPPED);
        }
        intent.stopWithin(Math.max(0, u), "target");
        double aim = Math.max(laneCentre - LATERAL_FREEDOM, Math.min(laneCentre + LATERAL_FREEDOM, v));
        // aiming no nearer than the direct distance keeps the turn gentle: a sharp one in the last
        // metres swings the body (it turns about its rear axle) over the centre line or the kerb
        intent.steer(lane.bearing() - Math.toDegrees(Math.atan2(aim, Math.max(DIRECT_DISTANCE, u))), "target");
    }

    private static boolean inLane(double v, double laneCentre) {
        return v > laneCentre - 1.6 && v < laneCentre + 1.6;
    }
}
