package sitcov.builtin;

import sitcov.faults.Fault;
import sitcov.faults.FaultSwitchboard;
import sitcov.geom.Bearing;
import sitcov.geom.Compass;
import sitcov.sensors.Lidar;
import sitcov.sensors.TrafficSensor;
import sitcov.vehicles.Dynamics;
import sitcov.vehicles.Lanes;

/**
 * Passing parked cars (faults/README.md, "The car under test, the traffic and the oracle"): seeing a parked
 * car ahead in its lane, the car pulls out
 * only if the oncoming lane is predicted clear for the whole manoeuvre, otherwise it waits
 * behind. It passes the whole row it can see — the LIDAR cannot see through the first car, so the
 * row is re-examined once pulled out — and pulls back in before anything parked on the other side.
 */
final class Overtaker {
    static final double HEADWAY = 7;
    static final double BUFFER = 2;
    static final double PULL_OUT = 2.6;
    static final double STRAIGHTENING = 0.3;
    static final double START_BEFORE = 3.5;
    static final double WAIT_GAP = 6;
    /** How close to the parked car ahead the car may creep to get past one parked beside it. */
    static final double CREEP_GAP = 2.5;
    /** Blocked this close while out in the other lane, the car pulls back in, aiming this far ahead. */
    static final double PULL_IN_EARLY = 8;
    static final double PULL_IN_AHEAD = 4;
    static final double PASSING_SPEED = 1.5;
    static final double TIGHT_SPEED = 0.6;
    static final double PARKED_CAR_LENGTH = 5;
    static final double SAFETY_MARGIN = 8;
    static final double MAX_PULL_OUT_ANGLE = 40;
    /** A Target in a gap of the row needs this much free lane beyond it for the car's front. */
    static final double GAP_BEYOND_TARGET = 0.8;
    /** The shortest way back into the lane, at the tight passing speed. */
    static final double TIGHT_RETURN = 2.5;
    /** A Target closer than the tight return past the row, but at least this far, is turned in to sharply. */
    static final double SHARP_RETURN = 1.0;

    private BuiltinCar car;
    private FaultSwitchboard faults;
    private SqueezeIn squeezeIn;
    private ParkedCarSightings sightings;
    private OvertakingStage stage = OvertakingStage.NOT_OVERTAKING;
    private int waypoint;
    private double oppositeStart = Double.NaN;
    private boolean toTarget;
    private Compass lane;

    Overtaker(BuiltinCar car, FaultSwitchboard faults) {
        this.car = car;
        this.faults = faults;
        this.squeezeIn = new SqueezeIn(car);
        this.sightings = new ParkedCarSightings(car, faults);
    }

    OvertakingStage stage() {
        return stage;
    }

    void plan(Intent intent, Compass currentLane, double laneCentre) {
        if (stage.isPassing()) {
            pass(intent, laneCentre);
            return;
        }
        lane = currentLane;
        ParkedCarSightings.Sighting s = sightings.look(lane, laneCentre);
        if (Double.isNaN(s.nearest()) || s.nearest() > Lidar.RANGE) {
            stage = OvertakingStage.NOT_OVERTAKING;
            return;
        }
        var target = car.target().position();
        double targetU = LaneFrame.u(lane, car.x(), car.y(), target.x(), target.y());
        double targetV = LaneFrame.v(lane, car.x(), car.y(), target.x(), target.y());
        if (targetU > -1 && targetU < s.nearest() && Math.abs(targetV - laneCentre) < 1.6) {
            // the Target comes before the parked car: reach it, do not pull out round the car
            stage = OvertakingStage.NOT_OVERTAKING;
            return;
        }
        if (s.oppositeBeside()) {
            // a car parked on the other side right beside it: creep on past it before pulling out
            intent.stopWithin(s.nearest() - CREEP_GAP, "overtaking");
            return;
        }
        intent.stopWithin(s.nearest() - WAIT_GAP, "overtaking");
        if (s.nearest() > HEADWAY + car.speed()) {
            return;
        }
        double passEnd = Math.max(s.farthest(), s.nearest() + PARKED_CAR_LENGTH) + BUFFER + 1;
        double finish = passEnd + HEADWAY;
        boolean tight = false;
        if (!Double.isNaN(s.opposite()) && s.opposite() < finish + BUFFER) {
            if (s.opposite() < passEnd + 2.5) {
                stage = OvertakingStage.WAITING;
                return;
            }
            finish = s.opposite() - 1;
            tight = true;
        }
        if (!oncomingLaneClear(laneCentre, finish)) {
            stage = OvertakingStage.WAITING;
            return;
        }
        // remembered as a coordinate along the road, so it stays put while the car moves
        oppositeStart = tight ? along() + s.opposite() * Lanes.forwardSign(lane) : Double.NaN;
        // the start point is pulled out a little further than the pass itself: straightening up
        // afterwards swings the car's front (it turns about its rear axle) back towards the kerb
        double u = Math.max(2, s.nearest() - START_BEFORE);
        waypoint = createWaypoint(u, laneCentre + PULL_OUT + STRAIGHTENING, Waypoint.Kind.OVERTAKE_START);
        stage = OvertakingStage.START;
        pass(intent, laneCentre);
    }

    private void pass(Intent intent, double laneCentre) {
        Waypoint wp = car.waypoints().lookup(waypoint);
        if (wp == null) {
            end();
            return;
        }
        intent.limit(Double.isNaN(oppositeStart) && !toTarget ? PASSING_SPEED : TIGHT_SPEED, "overtaking");
        if (squeezeIn.isOn() && stage == OvertakingStage.FINISH) {
            if (!squeezeIn.steer(intent, laneCentre)) {
                end();
            }
            return;
        }
        double blocked = sightings.parkedCarInTheWay(lane);
        if (!Double.isNaN(blocked)) {
            intent.stopWithin(blocked - 0.7, "overtaking");
            if (stage == OvertakingStage.PULLED_OUT && blocked < PULL_IN_EARLY && sightings.ownLaneFreeBeside(laneCentre)) {
                // something stands in the other lane ahead: back into its own lane now, while there is room
                replace(PULL_IN_AHEAD, laneCentre, Waypoint.Kind.OVERTAKE_FINISH);
                stage = OvertakingStage.FINISH;
            }
        }
        double ahead = LaneFrame.u(lane, car.x(), car.y(), wp.x(), wp.y());
        double aside = LaneFrame.v(lane, car.x(), car.y(), wp.x(), wp.y());
        if (stage == OvertakingStage.FINISH && ahead <= Math.max(1, car.speed() / 2)) {
            // back in only once the whole car is in its lane and straight, or the pass would end over the line
            if (Math.abs(laneCentre) < 0.3 && Math.abs(Bearing.turn(car.heading(), lane.bearing())) < 6) {
                end();
                return;
            }
            intent.steer(lane.bearing() - Math.toDegrees(Math.atan2(laneCentre, BuiltinCar.LOOKAHEAD)), "overtaking");
            return;
        }
        // pulling out is only done once the car is across, not merely level with the waypoint
        boolean outFarEnough = stage != OvertakingStage.START || Math.abs(aside) < 0.3;
        if ((ahead <= Math.max(1, car.speed() / 2) && outFarEnough) || ahead < -1) {
            advance(laneCentre, wp);
            wp = car.waypoints().lookup(waypoint);
            if (wp == null || stage == OvertakingStage.NOT_OVERTAKING) {
                return;
            }
        }
        double bearing = Bearing.between(car.x(), car.y(), wp.x(), wp.y());
        if (stage == OvertakingStage.START) {
            // a pull-out from close behind the parked car would swing the car's corners off the far
            // side of the road: it pulls out at a bounded angle, inching on while the way is tight
            double turn = Bearing.turn(lane.bearing(), bearing);
            bearing = lane.bearing() + Math.max(-MAX_PULL_OUT_ANGLE, Math.min(MAX_PULL_OUT_ANGLE, turn));
        }
        if (faults.watches(Fault.STOPS_TURNING_WHILE_OVERTAKING)) {
            if (Math.abs(Bearing.turn(car.heading(), bearing)) > 1e-9) {
                faults.effective(Fault.STOPS_TURNING_WHILE_OVERTAKING);
            } else {
                faults.reached(Fault.STOPS_TURNING_WHILE_OVERTAKING);
            }
            if (Double.compare(bearing, car.heading()) != 0) {
                faults.departs(Fault.STOPS_TURNING_WHILE_OVERTAKING); // a turn too small to count still steers
            }
            if (faults.isActive(Fault.STOPS_TURNING_WHILE_OVERTAKING)) {
                bearing = car.heading();
            }
        }
        intent.steer(bearing, "overtaking");
    }

    private void advance(double laneCentre, Waypoint reached) {
        switch (stage) {
            case START -> {
                ParkedCarSightings.Sighting s = sightings.look(lane, laneCentre);
                double farthest = Double.isNaN(s.farthest()) ? PARKED_CAR_LENGTH : s.farthest();
                if (faults.watches(Fault.SECOND_PULL_OUT) && farthest > 6) {
                    faults.effective(Fault.SECOND_PULL_OUT);
                }
                if (faults.isActive(Fault.SECOND_PULL_OUT) && farthest > 6) {
                    replace(farthest - BUFFER, LaneFrame.v(lane, car.x(), car.y(), reached.x(), reached.y()) + PULL_OUT,
                            Waypoint.Kind.OVERTAKE_START);
                    return;
                }
                double out = pulledOutUntil(farthest, laneCentre);
                replace(out, laneCentre + PULL_OUT, Waypoint.Kind.OVERTAKE_PULLED_OUT);
                stage = OvertakingStage.PULLED_OUT;
            }
            case PULLED_OUT -> {
                if (squeezeIn.isOn()) {
                    stage = OvertakingStage.FINISH;
                    return;
                }
                ParkedCarSightings.Sighting s = sightings.look(lane, laneCentre);
                boolean rowBeforeTarget = !toTarget
                        || !Double.isNaN(sightings.farthestParkedBefore(targetAheadInLane(laneCentre), laneCentre));
                if (!Double.isNaN(s.farthest()) && s.farthest() > 0 && rowBeforeTarget) {
                    // another parked car came into view beyond the one passed: keep passing
                    replace(pulledOutUntil(s.farthest(), laneCentre), laneCentre + PULL_OUT, Waypoint.Kind.OVERTAKE_PULLED_OUT);
                    return;
                }
                double back = HEADWAY;
                if (!Double.isNaN(oppositeStart)) {
                    back = Math.max(2.5, Math.min(HEADWAY, oppositeRemaining() - 1));
                }
                double target = targetAheadInLane(laneCentre);
                double in = laneCentre;
                if ((toTarget || target < back + TargetSeeker.CAPTURE_DISTANCE) && sightings.ownLaneFreeBeside(laneCentre)) {
                    // the Target lies just past the parked cars: pull back in at it, as a driver would
                    back = Math.max(TIGHT_RETURN, Math.min(back, target));
                    toTarget = true;
                    // aim at the Target's side of the lane, as far as the body stays in the lane
                    in = Math.max(laneCentre - TargetSeeker.LATERAL_FREEDOM,
                            Math.min(laneCentre + TargetSeeker.LATERAL_FREEDOM, targetAside()));
                }
                replace(back, in, Waypoint.Kind.OVERTAKE_FINISH);
                stage = OvertakingStage.FINISH;
            }
            case FINISH -> end();
            default -> {
                // not passing: nothing to advance
            }
        }
    }

    /**
     * How far ahead the car stays out to pass a row whose farthest seen car is {@code farthest}
     * ahead, and whether it then pulls in at a Target just past the row.
     */
    private double pulledOutUntil(double farthest, double laneCentre) {
        double out = farthest + BUFFER + 1;
        double target = targetAheadInLane(laneCentre);
        // the Target may lie in a gap of the row: what matters is the row up to the Target
        double before = sightings.farthestParkedBefore(target, laneCentre);
        double rowEnd = Double.isNaN(before) ? farthest : before;
        if (!Double.isNaN(sightings.farthestParkedBefore(target + GAP_BEYOND_TARGET, laneCentre, target))) {
            return out;
        }
        if (target > rowEnd + TIGHT_RETURN && target < rowEnd + BUFFER + 1 + HEADWAY + TargetSeeker.CAPTURE_DISTANCE) {
            // the Target lies just past the row, with room to get in before it: stay out only
            // until the row is passed, then pull in at it
            toTarget = true;
            return Math.max(rowEnd + BUFFER, Math.min(rowEnd + BUFFER + 1, target - TIGHT_RETURN));
        }
        if (target > rowEnd + SHARP_RETURN && target <= rowEnd + TIGHT_RETURN) {
            // too close past the row for a tight return: the car turns in sharply at it once its
            // tail is past the row, as a driver squeezes in ahead of a parked car
            toTarget = true;
            squeezeIn.begin(lane, rowEnd);
            return rowEnd + SqueezeIn.CLEARANCE;
        }
        return out;
    }

    /** Metres from the car to the parked car on the other side that the pass must end before. */
    private double oppositeRemaining() {
        return (oppositeStart - along()) * Lanes.forwardSign(lane);
    }

    private double along() {
        return Lanes.along(lane, car.x(), car.y());
    }

    private void end() {
        car.waypoints().remove(waypoint);
        stage = OvertakingStage.NOT_OVERTAKING;
        oppositeStart = Double.NaN;
        toTarget = false;
        squeezeIn.end();
    }

    /** Where the Target lies across the lane frame, from the car. */
    private double targetAside() {
        var target = car.target().position();
        return LaneFrame.v(lane, car.x(), car.y(), target.x(), target.y());
    }

    /** How far ahead the Target lies when it is in the car's own lane ahead, else infinity. */
    private double targetAheadInLane(double laneCentre) {
        var target = car.target().position();
        double u = LaneFrame.u(lane, car.x(), car.y(), target.x(), target.y());
        double v = LaneFrame.v(lane, car.x(), car.y(), target.x(), target.y());
        return u > 0 && Math.abs(v - laneCentre) < 1.6 ? u : Double.POSITIVE_INFINITY;
    }

    private void replace(double u, double v, Waypoint.Kind kind) {
        car.waypoints().remove(waypoint);
        waypoint = createWaypoint(u, v, kind);
    }

    private int createWaypoint(double u, double v, Waypoint.Kind kind) {
        return car.waypoints().create(LaneFrame.x(lane, car.x(), u, v), LaneFrame.y(lane, car.y(), u, v), kind);
    }

    private boolean oncomingLaneClear(double laneCentre, double finish) {
        TrafficSensor traffic = car.traffic();
        double ticks = ticksToTravel(finish);
        boolean clearOfOncoming = clearOf(traffic.oncomingGap(), traffic.oncomingSpeed(), ticks, finish);
        if (faults.watches(Fault.ONCOMING_AT_HALF_SPEED) && Double.isFinite(traffic.oncomingGap())) {
            boolean misjudged = clearOf(traffic.oncomingGap(), traffic.oncomingSpeed() / 2, ticks, finish);
            if (misjudged != clearOfOncoming) {
                faults.effective(Fault.ONCOMING_AT_HALF_SPEED);
            } else {
                faults.reached(Fault.ONCOMING_AT_HALF_SPEED);
            }
            if (faults.isActive(Fault.ONCOMING_AT_HALF_SPEED)) {
                clearOfOncoming = misjudged;
            }
        }
        // anything in the other lane where the pass will be (a car standing there, one alongside)
        return clearOfOncoming && traffic.otherLaneGap() > finish + SAFETY_MARGIN;
    }

    private static boolean clearOf(double gap, double speed, double ticks, double finish) {
        return gap - speed * ticks > finish + SAFETY_MARGIN;
    }

    /** Ticks to travel {@code distance} from the current speed, accelerating up to the passing speed. */
    private double ticksToTravel(double distance) {
        double v = car.speed();
        double covered = 0;
        int ticks = 0;
        while (covered < distance && ticks < 1000) {
            double next = Math.min(PASSING_SPEED, v + Dynamics.ACCELERATION);
            covered += (v + next) / 2;
            v = next;
            ticks++;
        }
        return ticks;
    }

}
