package sitcov.builtin;

import java.util.List;
import java.util.random.RandomGenerator;
import sitcov.control.Vehicle;
import sitcov.faults.Fault;
import sitcov.faults.FaultSwitchboard;
import sitcov.geom.Bearing;
import sitcov.geom.Compass;
import sitcov.vehicles.CrossingPath;
import sitcov.vehicles.Dynamics;
import sitcov.vehicles.JunctionRules;
import sitcov.vehicles.Lanes;
import sitcov.world.Junction;
import sitcov.world.Road;

/**
 * The autonomous car at junctions (faults/README.md, "The car under test, the traffic and the oracle"): slows
 * on the approach, asks for the junction
 * before entering and waits at the square's edge while another vehicle holds it, then crosses
 * towards the exit it chose — exits not yet taken first, then the one nearest the Target along the
 * roads ({@link Route}), and when
 * every exit was taken, each competes with probability 0.8^(times taken). Dead ends are left by a
 * U-turn through the square.
 */
final class JunctionDriver {
    static final double APPROACH_SPEED = 2.0;
    static final double STRAIGHT_SPEED = 1.5;
    static final double RIGHT_TURN_SPEED = 0.8;
    /** The fastest the car follows the left-turn arc (radius 1.5 m) at 15° a tick. */
    static final double LEFT_TURN_SPEED = 0.38;
    /** The straight legs of a U-turn, either side of turning on the spot. */
    static final double U_TURN_SPEED = 0.5;
    static final double CRAWL_BEFORE_TURNING = 1.0;
    /** Room the car wants in its exit lane beyond the square before it enters, and what counts as blocking it. */
    static final double EXIT_ROOM = 6;
    static final double EXIT_BLOCKED_SPEED = 0.5;
    /** While crossing, a junction whose square begins within this distance is asked for already. */
    static final double LOOK_BEYOND = 12;

    private BuiltinCar car;
    private FaultSwitchboard faults;
    private RandomGenerator decisions;
    private Route route;
    private int[][] exitsTaken;
    private int held = -1;
    private int reserved = -1;
    private Compass reservedExit;
    private Compass arrival;
    private Compass exit;
    private int waypoint;
    private CrossingPath path;
    private sitcov.geom.Vec2 junctionCentre;
    private double finishBeyond;
    private boolean crossing;
    private boolean waiting;
    /** The junction the car last waited short of: it creeps up to that square's edge (faults 5 and 6 act there). */
    private int waitedFor = -1;

    JunctionDriver(BuiltinCar car, FaultSwitchboard faults, RandomGenerator decisions, Route route, int junctions) {
        this.car = car;
        this.faults = faults;
        this.decisions = decisions;
        this.route = route;
        this.exitsTaken = new int[junctions][4];
    }

    boolean isCrossing() {
        return crossing;
    }

    boolean isWaiting() {
        return waiting;
    }

    /** Lets go of the junction once the car's whole footprint has left its square. */
    void releaseIfLeft() {
        if (held >= 0 && !crossing) {
            Junction j = car.roads().junctions().get(held);
            if (!car.footprint().overlaps(j.square())) {
                car.rightOfWay().release(held);
                held = -1;
            }
        }
    }

    void plan(Intent intent, Compass lane) {
        waiting = false;
        if (crossing) {
            cross(intent);
            lookBeyond(intent);
            return;
        }
        Road road = car.road(lane);
        if (road == null) {
            return;
        }
        Junction next = Lanes.nextJunction(car.roads(), road, lane, car.x(), car.y(), -1);
        if (next != null && recognises(next)) {
            approach(intent, lane, next, Lanes.distanceToSquare(next, lane, car.x(), car.y()));
        }
    }

    /** While crossing, asks in good time for a junction that follows right after this one. */
    private void lookBeyond(Intent intent) {
        if (!crossing) {
            return;
        }
        Road road = Lanes.roadAlong(car.roads(), car.x(), car.y(), exit);
        Junction next = road == null ? null
                : Lanes.nextJunction(car.roads(), road, exit, car.x(), car.y(), held);
        if (next != null && recognises(next)) {
            double d = Lanes.distanceToSquare(next, exit, car.x(), car.y());
            if (d < LOOK_BEYOND) {
                approach(intent, exit, next, d);
            }
        }
    }

    private void approach(Intent intent, Compass lane, Junction next, double d) {
        if (d > sitcov.world.Dimensions.APPROACH_LENGTH) {
            return;
        }
        intent.limit(Dynamics.speedToSlowTo(APPROACH_SPEED, d), "junction");
        if (next.id() == reserved && !crossing) {
            // the junction asked for while crossing the one before becomes the one held
            if (held >= 0) {
                car.rightOfWay().release(held);
            }
            held = reserved;
            exit = reservedExit;
            reserved = -1;
        }
        if ((next.id() == held || next.id() == reserved) && !crossing
                && !car.rightOfWay().isHeld(next.id())) {
            // its hold went stale and another vehicle took the junction over: ask again
            if (next.id() == held) {
                held = -1;
            } else {
                reserved = -1;
            }
        }
        if (next.id() == held || next.id() == reserved) {
            Compass leaving = next.id() == held ? exit : reservedExit;
            if (d > 0 && !exitIsClear(next, leaving)) {
                // do not enter a junction without room to leave it: wait short of the square
                waitShortOf(intent, next, d);
                return;
            }
            if (d <= 0 && !crossing) {
                startCrossing(next, lane);
                cross(intent);
            } else {
                pullUp(intent, next, entrySpeed(lane, next.id() == held ? exit : reservedExit), d);
            }
            return;
        }
        if (d > Dynamics.stoppingDistance(car.speed()) + 2) {
            return;
        }
        // a stale hold is only taken over once the square is seen to be empty
        if (car.rightOfWay().request(next.id())) {
            Compass chosen = chooseExit(next, lane);
            if (crossing) {
                reserved = next.id();
                reservedExit = chosen;
            } else {
                if (held >= 0 && held != next.id()) {
                    car.rightOfWay().release(held);
                }
                held = next.id();
                exit = chosen;
            }
            if (!exitIsClear(next, chosen)) {
                // granted the junction so close to it that it would be in before looking at the exit
                waitShortOf(intent, next, d);
                return;
            }
            pullUp(intent, next, entrySpeed(lane, chosen), d);
            return;
        }
        waiting = true;
        waitedFor = next.id();
        if (faults.watches(Fault.CREEPS_WHILE_WAITING)) {
            if (car.speed() > 0 || d > JunctionRules.WAIT_SHORT_OF_SQUARE) {
                faults.effective(Fault.CREEPS_WHILE_WAITING);
            } else {
                faults.reached(Fault.CREEPS_WHILE_WAITING);
            }
            // crawling is another intent than stopping, even for a car already stopped at the line
            faults.departs(Fault.CREEPS_WHILE_WAITING);
        }
        if (faults.isActive(Fault.CREEPS_WHILE_WAITING)) {
            intent.crawl();
        } else {
            intent.stopWithin(d - JunctionRules.WAIT_SHORT_OF_SQUARE, "junction");
        }
    }

    /** Slows to the entry speed at the square's edge; crawls there after waiting for the junction. */
    private void pullUp(Intent intent, Junction junction, double entrySpeed, double d) {
        intent.limit(Dynamics.speedToSlowTo(entrySpeed, d), "junction");
        if (junction.id() == waitedFor) {
            // a careful driver who had to wait pulls up to the edge slowly: the view into the
            // junction opens only there
            intent.crawl();
        }
    }

    private void waitShortOf(Intent intent, Junction junction, double d) {
        waiting = true;
        waitedFor = junction.id();
        intent.stopWithin(d - JunctionRules.WAIT_SHORT_OF_SQUARE, "junction");
    }

    /** Whether the exit lane just beyond the square is free of other vehicles (the radar sees it). */
    private boolean exitIsClear(Junction junction, Compass leaving) {
        if (!junction.hasArm(leaving)) {
            return true;
        }
        double half = sitcov.world.Dimensions.HALF_ROAD;
        var a = junction.exitPoint(leaving, 0);
        var b = junction.exitPoint(leaving, EXIT_ROOM);
        Compass side = leaving.left();
        double w = sitcov.world.Dimensions.LANE_WIDTH / 2;
        sitcov.geom.Rect lane = sitcov.geom.Rect.spanning(a.x() - side.dx() * w, a.y() - side.dy() * w,
                b.x() + side.dx() * w, b.y() + side.dy() * w);
        for (Vehicle v : car.trafficTracks()) {
            if ( Math.abs(v.x() - junction.centre().x()) < half + EXIT_ROOM + 6
                    && Math.abs(v.y() - junction.centre().y()) < half + EXIT_ROOM + 6 && v.footprint().overlaps(lane)
                    && v.speed() < EXIT_BLOCKED_SPEED) {
                return false;
            }
        }
        return true;
    }

    /** Fault 7: only the first half of the junctions (in map order) is recognised. */
    private boolean recognises(Junction junction) {
        if (!faults.watches(Fault.HALF_THE_JUNCTIONS)) {
            return true;
        }
        int half = car.roads().junctions().size() / 2;
        if (junction.id() < half) {
            faults.reached(Fault.HALF_THE_JUNCTIONS);
            return true;
        }
        faults.effective(Fault.HALF_THE_JUNCTIONS);
        return !faults.isActive(Fault.HALF_THE_JUNCTIONS);
    }

    private void startCrossing(Junction junction, Compass lane) {
        arrival = lane;
        waitedFor = -1;
        var point = junction.exitPoint(exit, JunctionRules.EXIT_BEYOND_SQUARE);
        waypoint = car.waypoints().create(point.x(), point.y(), Waypoint.Kind.JUNCTION_EXIT);
        Waypoint wp = car.waypoints().lookup(waypoint);
        junctionCentre = junction.centre();
        finishBeyond = CrossingPath.finishBeyond(car.roads(), junction, exit, wp.x(), wp.y());
        path = CrossingPath.between(car.x(), car.y(), arrival, wp.x(), wp.y(), exit, junction.centre().x(),
                junction.centre().y(), BuiltinCar.REAR_AXLE);
        crossing = true;
        exitsTaken[junction.id()][exit.ordinal()]++;
    }

    private void cross(Intent intent) {
        Waypoint wp = car.waypoints().lookup(waypoint);
        if (wp == null) {
            crossing = false;
            return;
        }
        // the crossing ends half-way along the path's tail beyond the waypoint, the car aligned with its lane
        double beyond = (car.x() - wp.x()) * exit.dx() + (car.y() - wp.y()) * exit.dy();
        boolean strayed = junctionCentre.distanceTo(car.x(), car.y()) > JunctionRules.STRAYED;
        if (beyond > finishBeyond || path.isFinished() || strayed) {
            crossing = false;
            car.waypoints().remove(waypoint);
            car.setLane(exit);
            return;
        }
        path.turned(car.heading());
        intent.steer(path.bearing(car), "junction");
        intent.limit(entrySpeed(arrival, exit), "junction");
        if (path.isTurningOnTheSpot()) {
            intent.limit(0, "junction");
            return;
        }
        double toTurn = path.distanceToTurnOnTheSpot(car);
        intent.stopWithin(toTurn, "junction");
        if (toTurn < CRAWL_BEFORE_TURNING) {
            // the last stretch before turning on the spot is crawled (faults 5 and 6 act here)
            intent.crawl();
        }
    }

    /** How fast to enter and cross: straight on is quickest; left turns and U-turns crawl. */
    private static double entrySpeed(Compass lane, Compass exit) {
        if (exit == lane) {
            return STRAIGHT_SPEED;
        }
        if (exit == lane.right()) {
            return RIGHT_TURN_SPEED;
        }
        return exit == lane.left() ? LEFT_TURN_SPEED : U_TURN_SPEED;
    }

    private Compass chooseExit(Junction junction, Compass heading) {
        List<Compass> arms = junction.arms();
        int[] taken = exitsTaken[junction.id()];
        for (int pass = 0; pass < 1000; pass++) {
            Compass best = null;
            double bestDistance = Double.POSITIVE_INFINITY;
            for (Compass c : new Compass[] {Compass.EAST, Compass.SOUTH, Compass.WEST, Compass.NORTH}) {
                if (!arms.contains(c)) {
                    continue;
                }
                int count = taken[c.ordinal()];
                boolean eligible = count == 0 || (pass > 0 && decisions.nextDouble() < Math.pow(0.8, count));
                if (eligible) {
                    double turn = c == heading.opposite() ? Route.U_TURN_COST : 0;
                    double distance = route.distance(junction, c) + turn;
                    if (best == null || distance < bestDistance) {
                        best = c;
                        bestDistance = distance;
                    }
                }
            }
            if (best != null) {
                return best;
            }
        }
        return arms.get(0);
    }
}
