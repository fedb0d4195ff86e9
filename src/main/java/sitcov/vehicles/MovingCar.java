package sitcov.vehicles;

import java.util.ArrayList;
import java.util.List;
import java.util.random.RandomGenerator;
import sitcov.control.Vehicle;
import sitcov.engine.SimState;
import sitcov.engine.Steppable;
import sitcov.geom.Bearing;
import sitcov.geom.Box;
import sitcov.geom.Compass;
import sitcov.geom.Rect;
import sitcov.geom.Vec2;
import sitcov.world.Dimensions;
import sitcov.world.Junction;
import sitcov.world.Road;
import sitcov.world.StartPose;

/**
 * A moving car: a human driver who knows the map (ground truth). It keeps its lane, keeps its
 * distance to whatever is ahead, passes parked cars when the other lane is clear, takes a random
 * exit at junctions (U-turns allowed), and at a dead end turns back or leaves the map; a car that
 * leaves is replaced by one entering at a random dead end.
 */
public final class MovingCar implements Bodied, Steppable {
    /** The stream exits at junctions are drawn from. */
    public static final String CHOICES_STREAM = "traffic.choices";
    /** The stream replacement cars' dead ends are drawn from. */
    public static final String RESPAWNS_STREAM = "traffic.respawns";
    static final long PATIENCE = 30;
    static final double APPROACH_SPEED = 1.0;
    static final double JUNCTION_SPEED = 0.5;
    static final double U_TURN_SPEED = 0.3;
    static final double LOOKAHEAD = 5;
    static final double GAP = 2;
    /** How deep inside a road's surface (metres) a front centre puts the footprint on the road beyond doubt. */
    private static final double DEEP = 0.01;
    /** Ticks standing still after which the driver stops waiting for other standing moving cars. */
    static final int IMPATIENCE = 40;
    /**
     * Ticks standing still (10 s) after which the driver gives up and leaves the map, to be
     * replaced at a dead end: traffic never locks up for good, around the autonomous car or not.
     */
    static final int GIVE_UP = 50;
    /** Its rear axle, which it turns about, is this far behind its front. */
    public static final double REAR_AXLE = 3.5;

    private int id;
    private Scene scene;
    private RandomGenerator choices;
    private RandomGenerator respawns;
    private Body body;
    private boolean active = true;
    private Compass lane;
    private int held = -1;
    private Compass exit;
    private boolean crossing;
    private CrossingPath path;
    private double finishBeyond;
    private boolean leaving;
    private double waypointX;
    private double waypointY;
    private boolean passing;
    private double passEnd;
    private int stoppedFor;
    private Clearance clearance = new Clearance();

    MovingCar(int id, Scene scene, StartPose start, RandomGenerator choices, RandomGenerator respawns) {
        this.id = id;
        this.scene = scene;
        this.choices = choices;
        this.respawns = respawns;
        this.body = new Body(start.position().x(), start.position().y(), start.heading().bearing(), REAR_AXLE);
        this.lane = start.heading();
    }

    @Override
    public void step(SimState state) {
        if (!active) {
            reenter();
            return;
        }
        if (hasLeftTheRoads() || stoppedFor > GIVE_UP) {
            scene.occupancy().releaseAll(id);
            held = -1;
            crossing = false;
            active = false;
            stoppedFor = 0;
            return;
        }
        double limit = Dynamics.MAX_SPEED;
        double bearing = body.heading();
        if (crossing) {
            path.turned(body.heading());
            limit = Math.min(limit, exit == lane.left() || exit == lane.opposite() ? U_TURN_SPEED : JUNCTION_SPEED);
            limit = path.isTurningOnTheSpot() ? 0
                    : Math.min(limit, Dynamics.speedToStopWithin(path.distanceToTurnOnTheSpot(this)));
            bearing = path.bearing(this);
            double beyond = (body.x() - waypointX) * exit.dx() + (body.y() - waypointY) * exit.dy();
            if (beyond > finishBeyond || path.isFinished()
                    || fartherThan(body.x() - waypointX, body.y() - waypointY, JunctionRules.STRAYED)) {
                crossing = false;
                lane = exit;
            }
        } else {
            Road road = Lanes.roadAlong(scene.network(), body.x(), body.y(), lane);
            if (road != null) {
                limit = Math.min(limit, approachJunction(road));
                if (!crossing) {
                    limit = Math.min(limit, parkedCars(road));
                    bearing = laneBearing(road);
                }
            }
        }
        limit = Math.min(limit, Following.limit(scene, this, clearance, stoppedFor > IMPATIENCE));
        stoppedFor = body.speed() < 0.01 ? stoppedFor + 1 : 0;
        releaseJunctionIfLeft();
        if (clearance.anyoneNear(scene, this)
                && clearance.wouldTouch(scene, this, body.reachAfter(limit, bearing, Dynamics.MAX_TURN, length(), width()))) {
            // a driver who sees that the next move would leave no room to stop short of someone makes
            // an emergency stop (twice the planned braking, about 8 m/s²) and holds the wheel; it is
            // still bounded, so a car that cuts in close at speed can be hit
            body.brake();
            body.brake();
            body.move();
            return;
        }
        body.approachSpeed(limit);
        body.turnTowards(bearing, Dynamics.MAX_TURN);
        body.move();
    }

    private double approachJunction(Road road) {
        Junction next = Lanes.nextJunction(scene.network(), road, lane, body.x(), body.y());
        if (next == null) {
            return Dynamics.MAX_SPEED;
        }
        double d = Lanes.distanceToSquare(next, lane, body.x(), body.y());
        double limit = Dynamics.speedToSlowTo(APPROACH_SPEED, d);
        if (held == next.id() && !scene.occupancy().isHeldBy(held, id)) {
            held = -1; // its hold went stale and another vehicle took the junction over: ask again
        }
        if (held == next.id()) {
            if (d <= 0) {
                startCrossing(next);
                return JUNCTION_SPEED;
            }
            return Math.min(limit, Dynamics.speedToSlowTo(JUNCTION_SPEED, d));
        }
        if (d > Dynamics.stoppingDistance(body.speed()) + 2) {
            return limit;
        }
        if (!scene.isOccupiedByOther(next, this) && scene.occupancy().request(next.id(), id, scene.tick(), PATIENCE)) {
            if (held >= 0) {
                scene.occupancy().release(held, id);
            }
            held = next.id();
            return Math.min(limit, Dynamics.speedToSlowTo(JUNCTION_SPEED, d));
        }
        return Dynamics.speedToStopWithin(d - JunctionRules.WAIT_SHORT_OF_SQUARE);
    }

    private void startCrossing(Junction junction) {
        List<Compass> options = new ArrayList<>(junction.arms());
        if (junction.isDeadEnd()) {
            options.add(lane);
        }
        exit = options.get(choices.nextInt(options.size()));
        leaving = !junction.hasArm(exit);
        Vec2 point = leaving
                ? junction.exitPoint(exit, 12)
                : junction.exitPoint(exit, JunctionRules.EXIT_BEYOND_SQUARE);
        waypointX = point.x();
        waypointY = point.y();
        finishBeyond = CrossingPath.finishBeyond(scene.network(), junction, exit, waypointX, waypointY);
        path = CrossingPath.between(body.x(), body.y(), lane, waypointX, waypointY, exit,
                junction.centre().x(), junction.centre().y(), REAR_AXLE);
        crossing = true;
    }

    private void releaseJunctionIfLeft() {
        if (held >= 0 && !crossing) {
            Junction j = scene.network().junctions().get(held);
            if (!footprint().overlaps(j.square())) {
                scene.occupancy().release(held, id);
                held = -1;
            }
        }
    }

    /** Stops behind a parked car in its lane, or passes it when the other lane is clear. */
    private double parkedCars(Road road) {
        int sign = Lanes.forwardSign(lane);
        double along = road.along(body.x(), body.y());
        if (passing && (along - passEnd) * sign > 0) {
            passing = false;
        }
        double nearest = Double.MAX_VALUE;
        double end = Double.NaN;
        for (int each = 0, count = scene.parkedCars().size(); each < count; each++) {
            sitcov.world.ParkedCar car = scene.parkedCars().get(each);
            if (car.roadId() != road.id() || road.laneDirectionAt(car.centre().x(), car.centre().y()) != lane) {
                continue;
            }
            double ahead = (road.along(car.centre().x(), car.centre().y()) - along) * sign;
            if (ahead + Dimensions.CAR_LENGTH / 2 > 0 && ahead - Dimensions.CAR_LENGTH / 2 < nearest) {
                nearest = ahead - Dimensions.CAR_LENGTH / 2;
                end = ahead + Dimensions.CAR_LENGTH / 2;
            }
        }
        if (passing || nearest > 20) {
            if (passing && nearest < 20) {
                passEnd = along + sign * Math.max((passEnd - along) * sign, end + 4);
            }
            return Dynamics.MAX_SPEED;
        }
        if (otherLaneClear(road, along, sign, nearest, end + 8)) {
            passing = true;
            passEnd = along + sign * (end + 4);
            return 1.5;
        }
        return Dynamics.speedToStopWithin(nearest - 3);
    }

    private boolean otherLaneClear(Road road, double along, int sign, double from, double to) {
        Compass other = lane.opposite();
        for (int each = 0, count = scene.parkedCars().size(); each < count; each++) {
            sitcov.world.ParkedCar car = scene.parkedCars().get(each);
            if (car.roadId() == road.id() && road.laneDirectionAt(car.centre().x(), car.centre().y()) == other) {
                double ahead = (road.along(car.centre().x(), car.centre().y()) - along) * sign;
                if (ahead > from - 8 && ahead < to + 3) {
                    return false;
                }
            }
        }
        Junction next = Lanes.nextJunction(scene.network(), road, lane, body.x(), body.y());
        if (next != null && Lanes.distanceToSquare(next, lane, body.x(), body.y()) < to + 3) {
            return false;
        }
        for (int each = 0, count = scene.vehicles().size(); each < count; each++) {
            Vehicle v = scene.vehicles().get(each);
            if (v == this || !v.isActive() || !road.contains(v.x(), v.y())) {
                continue;
            }
            double ahead = (road.along(v.x(), v.y()) - along) * sign;
            boolean inOtherLane = road.laneDirectionAt(v.x(), v.y()) == other;
            if (inOtherLane && ahead > -8 && ahead < to + 60) {
                return false;
            }
        }
        return true;
    }

    private double laneBearing(Road road) {
        double across = road.laneCentre(lane) + (passing ? Lanes.rightSign(lane) * Dimensions.LANE_WIDTH : 0);
        double along = road.along(body.x(), body.y()) + Lanes.forwardSign(lane) * LOOKAHEAD;
        Vec2 aim = road.point(along, across);
        return Bearing.between(body.x(), body.y(), aim.x(), aim.y());
    }

    /** {@code Math.hypot(dx, dy) > limit}, told by the squares unless within a hair of the limit (hypot is slow). */
    private static boolean fartherThan(double dx, double dy, double limit) {
        double squared = dx * dx + dy * dy;
        double limitSquared = limit * limit;
        if (Math.abs(squared - limitSquared) > 1e-9 * limitSquared) {
            return squared > limitSquared;
        }
        return Math.hypot(dx, dy) > limit;
    }

    private boolean hasLeftTheRoads() {
        // the usual case, told without building the footprint: a front centre at least DEEP inside a
        // road's surface leaves a disc of radius DEEP / 2 of the footprint's interior on it, so the
        // footprint overlaps that surface far beyond Box's tolerance and the test below would say so too
        double x = body.x();
        double y = body.y();
        List<Rect> surfaces = scene.network().surfaces();
        for (int each = 0, count = surfaces.size(); each < count; each++) {
            Rect surface = surfaces.get(each);
            if (x > surface.minX() + DEEP && x < surface.maxX() - DEEP && y > surface.minY() + DEEP
                    && y < surface.maxY() - DEEP) {
                return false;
            }
        }
        Box footprint = footprint();
        for (int each = 0, count = surfaces.size(); each < count; each++) {
            if (footprint.overlaps(surfaces.get(each))) {
                return false;
            }
        }
        return true;
    }

    /** Enters again at a random dead end, if its square is free. */
    private void reenter() {
        List<Junction> deadEnds = scene.network().deadEnds();
        if (deadEnds.isEmpty()) {
            return;
        }
        Junction j = deadEnds.get(respawns.nextInt(deadEnds.size()));
        Compass into = j.arms().get(0);
        Vec2 entry = j.exitPoint(into, -Dimensions.JUNCTION_SIZE / 2 - 0.1);
        Box candidate = Box.behind(entry.x(), entry.y(), into.bearing(), length(), width());
        if (scene.occupancy().holder(j.id()) >= 0) {
            return;
        }
        for (int each = 0, count = scene.vehicles().size(); each < count; each++) {
            Vehicle v = scene.vehicles().get(each);
            if (v != this && v.isActive() && v.footprint().overlaps(candidate.bounds().expanded(2))) {
                return;
            }
        }
        body.place(entry.x(), entry.y(), into.bearing());
        lane = into;
        active = true;
        passing = false;
        crossing = false;
        scene.occupancy().request(j.id(), id, scene.tick(), PATIENCE);
        held = j.id();
    }

    @Override
    public int id() {
        return id;
    }

    @Override
    public double length() {
        return Dimensions.CAR_LENGTH;
    }

    @Override
    public double width() {
        return Dimensions.CAR_WIDTH;
    }

    @Override
    public boolean isActive() {
        return active;
    }

    @Override
    public Body body() {
        return body;
    }
}
