package sitcov.vehicles;

import sitcov.faults.Fault;
import sitcov.faults.FaultSwitchboard;
import sitcov.geom.Bearing;
import sitcov.geom.Box;
import sitcov.geom.Compass;
import sitcov.world.Dimensions;

/**
 * Passing parked cars (reference §3.7): seeing a parked car ahead in its lane, the car pulls out
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
    /** Half the width the car sweeps, with a margin: a parked car inside it is in the car's way. */
    static final double CORRIDOR = 1.15;
    /** A car parked on the other side less than this far behind the car's front still stands beside it. */
    static final double BESIDE = 2.5;
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
    /** How far past the row's end the car's front goes before it turns in sharply: its tail then clears the row. */
    static final double SHARP_CLEARANCE = 0.7;
    /** How far the car keeps its tail from the row's end it saw: the LIDAR sees that end only to a few tenths. */
    static final double TAIL_MARGIN = 0.6;
    /** Where the side of a row of parked cars lies, from the lane's centre towards the other lane, with a margin. */
    static final double ROW_FACE = 1.0;
    /** How deep, from its side to the kerb, the row is taken to be. */
    static final double ROW_DEPTH = 3;

    private final AutonomousCar car;
    private final FaultSwitchboard faults;
    private OvertakingStage stage = OvertakingStage.NOT_OVERTAKING;
    private int waypoint;
    private double oppositeStart = Double.NaN;
    private boolean toTarget;
    private boolean sharp;
    /** Where the row ends, as a coordinate along the road, while turning in sharply at the Target. */
    private double rowEndAlong = Double.NaN;
    private Compass lane;

    Overtaker(AutonomousCar car, FaultSwitchboard faults) {
        this.car = car;
        this.faults = faults;
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
        Sighting s = look(laneCentre);
        if (Double.isNaN(s.nearest) || s.nearest > Lidar.RANGE) {
            stage = OvertakingStage.NOT_OVERTAKING;
            return;
        }
        var target = car.scene().target().position();
        double targetU = LaneFrame.u(lane, car.x(), car.y(), target.x(), target.y());
        double targetV = LaneFrame.v(lane, car.x(), car.y(), target.x(), target.y());
        if (targetU > -1 && targetU < s.nearest && Math.abs(targetV - laneCentre) < 1.6) {
            // the Target comes before the parked car: reach it, do not pull out round the car
            stage = OvertakingStage.NOT_OVERTAKING;
            return;
        }
        if (s.oppositeBeside) {
            // a car parked on the other side right beside it: creep on past it before pulling out
            intent.stopWithin(s.nearest - CREEP_GAP, "overtaking");
            return;
        }
        intent.stopWithin(s.nearest - WAIT_GAP, "overtaking");
        if (s.nearest > HEADWAY + car.speed()) {
            return;
        }
        double passEnd = Math.max(s.farthest, s.nearest + PARKED_CAR_LENGTH) + BUFFER + 1;
        double finish = passEnd + HEADWAY;
        boolean tight = false;
        if (!Double.isNaN(s.opposite) && s.opposite < finish + BUFFER) {
            if (s.opposite < passEnd + 2.5) {
                stage = OvertakingStage.WAITING;
                return;
            }
            finish = s.opposite - 1;
            tight = true;
        }
        if (!oncomingLaneClear(laneCentre, finish)) {
            stage = OvertakingStage.WAITING;
            return;
        }
        // remembered as a coordinate along the road, so it stays put while the car moves
        oppositeStart = tight ? along() + s.opposite * Lanes.forwardSign(lane) : Double.NaN;
        // the start point is pulled out a little further than the pass itself: straightening up
        // afterwards swings the car's front (it turns about its rear axle) back towards the kerb
        double u = Math.max(2, s.nearest - START_BEFORE);
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
        if (sharp && stage == OvertakingStage.FINISH) {
            turnInAtTarget(intent, laneCentre);
            return;
        }
        double blocked = parkedCarInTheWay();
        if (!Double.isNaN(blocked)) {
            intent.stopWithin(blocked - 0.7, "overtaking");
            if (stage == OvertakingStage.PULLED_OUT && blocked < PULL_IN_EARLY && ownLaneFreeBeside(laneCentre)) {
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
            intent.steer(lane.bearing() - Math.toDegrees(Math.atan2(laneCentre, AutonomousCar.LOOKAHEAD)), "overtaking");
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
        if (faults.isActive(Fault.STOPS_TURNING_WHILE_OVERTAKING)) {
            if (Math.abs(Bearing.turn(car.heading(), bearing)) > 1e-9) {
                faults.effective(Fault.STOPS_TURNING_WHILE_OVERTAKING);
            } else {
                faults.reached(Fault.STOPS_TURNING_WHILE_OVERTAKING);
            }
            bearing = car.heading();
        }
        intent.steer(bearing, "overtaking");
    }

    private void advance(double laneCentre, Waypoint reached) {
        switch (stage) {
            case START -> {
                Sighting s = look(laneCentre);
                double farthest = Double.isNaN(s.farthest) ? PARKED_CAR_LENGTH : s.farthest;
                if (faults.isActive(Fault.SECOND_PULL_OUT) && farthest > 6) {
                    faults.effective(Fault.SECOND_PULL_OUT);
                    replace(farthest - BUFFER, LaneFrame.v(lane, car.x(), car.y(), reached.x(), reached.y()) + PULL_OUT,
                            Waypoint.Kind.OVERTAKE_START);
                    return;
                }
                double out = pulledOutUntil(farthest, laneCentre);
                replace(out, laneCentre + PULL_OUT, Waypoint.Kind.OVERTAKE_PULLED_OUT);
                stage = OvertakingStage.PULLED_OUT;
            }
            case PULLED_OUT -> {
                if (sharp) {
                    stage = OvertakingStage.FINISH;
                    return;
                }
                Sighting s = look(laneCentre);
                boolean rowBeforeTarget = !toTarget
                        || !Double.isNaN(farthestParkedBefore(targetAheadInLane(laneCentre), laneCentre));
                if (!Double.isNaN(s.farthest) && s.farthest > 0 && rowBeforeTarget) {
                    // another parked car came into view beyond the one passed: keep passing
                    replace(pulledOutUntil(s.farthest, laneCentre), laneCentre + PULL_OUT, Waypoint.Kind.OVERTAKE_PULLED_OUT);
                    return;
                }
                double back = HEADWAY;
                if (!Double.isNaN(oppositeStart)) {
                    back = Math.max(2.5, Math.min(HEADWAY, oppositeRemaining() - 1));
                }
                double target = targetAheadInLane(laneCentre);
                double in = laneCentre;
                if ((toTarget || target < back + TargetSeeker.CAPTURE_DISTANCE) && ownLaneFreeBeside(laneCentre)) {
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
        double before = farthestParkedBefore(target, laneCentre);
        double rowEnd = Double.isNaN(before) ? farthest : before;
        if (!Double.isNaN(farthestParkedBefore(target + GAP_BEYOND_TARGET, laneCentre, target))) {
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
            sharp = true;
            rowEndAlong = along() + rowEnd * Lanes.forwardSign(lane);
            return rowEnd + SHARP_CLEARANCE;
        }
        return out;
    }

    /** Metres from the car to the parked car on the other side that the pass must end before. */
    private double oppositeRemaining() {
        return (oppositeStart - along()) * Lanes.forwardSign(lane);
    }

    private double along() {
        return lane.isNorthSouth() ? car.y() : car.x();
    }

    private void end() {
        car.waypoints().remove(waypoint);
        stage = OvertakingStage.NOT_OVERTAKING;
        oppositeStart = Double.NaN;
        toTarget = false;
        sharp = false;
        rowEndAlong = Double.NaN;
    }

    /** Heads straight for the Target, slowing to stop on it; a Target missed ends the manoeuvre. */
    private void turnInAtTarget(Intent intent, double laneCentre) {
        var target = car.scene().target().position();
        double u = LaneFrame.u(lane, car.x(), car.y(), target.x(), target.y());
        if (u < -TargetSeeker.CAPTURE_DISTANCE) {
            end();
            return;
        }
        intent.stopWithin(target.distanceTo(car.x(), car.y()), "overtaking");
        double rowEnd = (rowEndAlong - along()) * Lanes.forwardSign(lane);
        double face = laneCentre + ROW_FACE;
        double heading = car.heading();
        double toward = Bearing.turn(heading, Bearing.between(car.x(), car.y(), target.x(), target.y()));
        double step = Math.max(-Dynamics.MAX_TURN, Math.min(Dynamics.MAX_TURN, toward));
        double speed = Math.min(car.speed() + Dynamics.ACCELERATION, TIGHT_SPEED);
        // the car turns about its rear axle, swinging its tail towards the row: it turns in only as
        // far as keeps that tail clear of the row's end, straightening up while it is not
        double bearing = heading + step;
        if (!tailClear(bearing, speed, rowEnd, face)) {
            bearing = tailClear(heading, speed, rowEnd, face) ? heading : lane.bearing();
        }
        intent.steer(bearing, "overtaking");
    }

    /**
     * Whether the car's footprint after turning to {@code bearing} (about its rear axle) and moving
     * {@code speed} keeps clear of the row: everything short of its end and beyond its side, with margins.
     */
    private boolean tailClear(double bearing, double speed, double rowEnd, double face) {
        double pivot = AutonomousCar.REAR_AXLE;
        double nx = car.x() - pivot * Bearing.dx(car.heading()) + (pivot + speed) * Bearing.dx(bearing);
        double ny = car.y() - pivot * Bearing.dy(car.heading()) + (pivot + speed) * Bearing.dy(bearing);
        Box next = Box.behind(nx, ny, bearing, Dimensions.AUTONOMOUS_CAR_LENGTH, Dimensions.AUTONOMOUS_CAR_WIDTH);
        double u = rowEnd + TAIL_MARGIN;
        double v = face - ROW_DEPTH / 2;
        Box row = Box.behind(LaneFrame.x(lane, car.x(), u, v), LaneFrame.y(lane, car.y(), u, v), lane.bearing(),
                PARKED_CAR_LENGTH, ROW_DEPTH);
        return !next.overlaps(row);
    }

    /** Where the Target lies across the lane frame, from the car. */
    private double targetAside() {
        var target = car.scene().target().position();
        return LaneFrame.v(lane, car.x(), car.y(), target.x(), target.y());
    }

    /** How far ahead the Target lies when it is in the car's own lane ahead, else infinity. */
    private double targetAheadInLane(double laneCentre) {
        var target = car.scene().target().position();
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
        if (faults.isActive(Fault.ONCOMING_AT_HALF_SPEED) && Double.isFinite(traffic.oncomingGap())) {
            boolean misjudged = clearOf(traffic.oncomingGap(), traffic.oncomingSpeed() / 2, ticks, finish);
            if (misjudged != clearOfOncoming) {
                faults.effective(Fault.ONCOMING_AT_HALF_SPEED);
            } else {
                faults.reached(Fault.ONCOMING_AT_HALF_SPEED);
            }
            clearOfOncoming = misjudged;
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

    /** Whether no parked car stands in the car's own lane from just behind it to a few metres ahead. */
    private boolean ownLaneFreeBeside(double laneCentre) {
        Lidar lidar = car.lidar();
        for (int h = 0; h < lidar.hits(); h++) {
            if (lidar.isParkedCar(h) && lidar.u(h) > -AutonomousCar.REAR_AXLE - 1 && lidar.u(h) < PULL_IN_AHEAD + 1
                    && Math.abs(lidar.v(h) - laneCentre) < 1.5) {
                return false;
            }
        }
        return true;
    }

    /** The farthest LIDAR hit on a parked car in the car's lane between it and {@code before} metres ahead, or NaN. */
    private double farthestParkedBefore(double before, double laneCentre) {
        return farthestParkedBefore(before, laneCentre, 0);
    }

    private double farthestParkedBefore(double before, double laneCentre, double from) {
        Lidar lidar = car.lidar();
        double farthest = Double.NaN;
        for (int h = 0; h < lidar.hits(); h++) {
            double u = lidar.u(h);
            if (lidar.isParkedCar(h) && u > from && u < before && Math.abs(lidar.v(h) - laneCentre) < 1.4) {
                farthest = Double.isNaN(farthest) ? u : Math.max(farthest, u);
            }
        }
        return farthest;
    }

    /** Distance to the nearest parked car inside the width the car sweeps ahead of it, or NaN. */
    private double parkedCarInTheWay() {
        Lidar lidar = car.lidar();
        int hits = lidar.sweep(car.x(), car.y(), lane.bearing(), lane, car.scene(), car);
        // the width the car sweeps lies along its heading, which pulling out turns away from the lane
        double phi = Math.toRadians(Bearing.turn(lane.bearing(), car.heading()));
        double cos = Math.cos(phi);
        double sin = Math.sin(phi);
        double nearest = Double.NaN;
        for (int h = 0; h < hits; h++) {
            double along = lidar.u(h) * cos - lidar.v(h) * sin;
            double across = lidar.u(h) * sin + lidar.v(h) * cos;
            if (lidar.isParkedCar(h) && along > 0 && Math.abs(across) < CORRIDOR) {
                nearest = Double.isNaN(nearest) ? along : Math.min(nearest, along);
            }
        }
        return nearest;
    }

    /** What the LIDAR shows of parked cars, in the lane frame. */
    private record Sighting(double nearest, double farthest, double opposite, boolean oppositeBeside) {
    }

    private Sighting look(double laneCentre) {
        Lidar lidar = car.lidar();
        if (!faults.isActive(Fault.OBSTACLE_SEARCH_ALONG_HEADING)) {
            lidar.sweep(car.x(), car.y(), lane.bearing(), lane, car.scene(), car);
            return sighting(lidar, laneCentre, 0);
        }
        // the faulty car takes the road to run along its heading: hits are read in the heading's frame
        int hits = lidar.sweep(car.x(), car.y(), car.heading(), lane, car.scene(), car);
        Sighting faulty = sighting(lidar, laneCentre, Math.toRadians(Bearing.turn(lane.bearing(), car.heading())));
        if (hits > 0 && !faulty.equals(sighting(lidar, laneCentre, 0))) {
            faults.effective(Fault.OBSTACLE_SEARCH_ALONG_HEADING);
        } else {
            faults.reached(Fault.OBSTACLE_SEARCH_ALONG_HEADING);
        }
        return faulty;
    }

    /** Parked cars in the lane ahead and on the other side, with the hits turned by {@code phi} first. */
    private static Sighting sighting(Lidar lidar, double laneCentre, double phi) {
        double cos = Math.cos(phi);
        double sin = Math.sin(phi);
        double nearest = Double.NaN;
        double farthest = Double.NaN;
        double opposite = Double.NaN;
        boolean beside = false;
        for (int h = 0; h < lidar.hits(); h++) {
            if (!lidar.isParkedCar(h)) {
                continue;
            }
            double u = lidar.u(h) * cos - lidar.v(h) * sin;
            double v = lidar.u(h) * sin + lidar.v(h) * cos;
            if (u > 0 && v > laneCentre - 1.4 && v < laneCentre + 1.4) {
                nearest = Double.isNaN(nearest) ? u : Math.min(nearest, u);
                farthest = Double.isNaN(farthest) ? u : Math.max(farthest, u);
            } else if (u > -BESIDE && v > laneCentre + 1.6 && v < laneCentre + 4.4) {
                if (u > 1) {
                    opposite = Double.isNaN(opposite) ? u : Math.min(opposite, u);
                } else {
                    beside = true;
                }
            }
        }
        return new Sighting(nearest, farthest, opposite, beside);
    }
}
