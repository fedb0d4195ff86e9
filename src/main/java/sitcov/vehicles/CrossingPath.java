package sitcov.vehicles;

import java.util.Arrays;
import sitcov.control.Vehicle;
import sitcov.geom.Bearing;
import sitcov.geom.Compass;
import sitcov.world.Dimensions;
import sitcov.world.Junction;
import sitcov.world.Road;
import sitcov.world.RoadNetwork;

/**
 * The path of the car's front through a junction square, from where it entered to its exit
 * waypoint and a short straight beyond. The car turns about its rear axle, so the path is planned
 * for the axle and the front's path is the axle's moved forward by the axle distance:
 * <ul>
 * <li>straight on: a straight line;</li>
 * <li>a turn: straight to where the incoming and outgoing lane centres cross, an arc round that
 * corner, straight out — a left turn's arc is centred on the kerb corner, so the body's inside
 * keeps off it, a right turn's is as wide as the square, so the front's outer corner stays on the road;</li>
 * <li>a U-turn: across to the road's centre line at the square's middle, a turn on the spot (a
 * 6 m road leaves no room for a 2 m car to swing round), and across to the other lane.</li>
 * </ul>
 * The car follows the path with a Stanley controller on its rear axle: the planned heading at
 * the nearest path point, corrected towards the path by the axle's cross-track error.
 */
public final class CrossingPath {
    /** The path runs on this far beyond the waypoint, along the exit lane, so the car leaves aligned. */
    public static final double TAIL = 4.0;
    static final double LEFT_TURN_RADIUS = 1.5;
    static final double RIGHT_TURN_RADIUS = 4.5;
    /** The tightest arc planned for a late turn. */
    static final double MIN_RADIUS = 1.0;
    /**
     * Where a U-turn turns on the spot, past the square's middle: turning sweeps 1.8 m round the
     * rear axle, and the square's far side may be a closed road end 3 m beyond its middle.
     */
    static final double U_TURN_BEYOND_CENTRE = 0.5;
    /** ...and half-way across the centre line towards the lane it turns into, which halves the last shift. */
    static final double U_TURN_ACROSS_CENTRE = 0.75;
    /** How hard the car steers back onto the path (per metre of cross-track error, per metre per tick of speed). */
    static final double CROSS_TRACK_GAIN = 1.5;
    /** Keeps the correction gentle at crawling speed, where the car would otherwise swerve. */
    static final double SOFTENING = 1.0;
    /** A turn on the spot is done when the heading is this close to the planned one. */
    static final double TURNED = 1.0;
    private static final int ARC_STEPS = 12;
    private static final double STEP = 0.5;
    private static final double MIN_STRAIGHT = 0.05;
    private static final double ROTATION_STEP = 15;

    private double axle;
    private double[] xs;
    private double[] ys;
    private double[] headings;
    /** The unit vectors of the headings, worked out once: the car steers by them every tick of a crossing. */
    private double[] headingDx;
    private double[] headingDy;
    private boolean[] onTheSpot;
    private int progress;

    private CrossingPath(double axle, double[] xs, double[] ys, double[] headings, boolean[] onTheSpot) {
        this.axle = axle;
        this.xs = xs;
        this.ys = ys;
        this.headings = headings;
        this.headingDx = new double[headings.length];
        this.headingDy = new double[headings.length];
        for (int i = 0; i < headings.length; i++) {
            headingDx[i] = Bearing.dx(headings[i]);
            headingDy[i] = Bearing.dy(headings[i]);
        }
        this.onTheSpot = onTheSpot;
    }

    /**
     * The path for a car whose front is at ({@code x0}, {@code y0}) arriving {@code arrival}, to
     * the waypoint ({@code wx}, {@code wy}) in the lane leaving {@code exit}, through the junction
     * centred at ({@code jx}, {@code jy}); the rear axle is {@code axle} metres behind the front.
     */
    public static CrossingPath between(double x0, double y0, Compass arrival, double wx, double wy, Compass exit,
                                double jx, double jy, double axle) {
        Builder path = new Builder(axle);
        path.start(x0 - arrival.dx() * axle, y0 - arrival.dy() * axle, arrival.bearing());
        double endX = wx - exit.dx() * axle;
        double endY = wy - exit.dy() * axle;
        if (exit == arrival) {
            path.straightTo(endX, endY);
        } else if (exit == arrival.opposite()) {
            // turn on the road's centre line, past the square's middle but clear of its far side
            Compass across = arrival.right();
            double tx = jx + arrival.dx() * U_TURN_BEYOND_CENTRE + across.dx() * U_TURN_ACROSS_CENTRE;
            double ty = jy + arrival.dy() * U_TURN_BEYOND_CENTRE + across.dy() * U_TURN_ACROSS_CENTRE;
            // a car that has already rolled past the turning point turns where it is
            double overshoot = ((x0 - arrival.dx() * axle) - tx) * arrival.dx() + ((y0 - arrival.dy() * axle) - ty) * arrival.dy();
            if (overshoot > 0) {
                tx += arrival.dx() * overshoot;
                ty += arrival.dy() * overshoot;
            }
            path.straightTo(tx, ty);
            path.turnOnTheSpot(Bearing.between(tx, ty, endX, endY), false);
            path.straightTo(endX, endY);
        } else {
            // the lane centres cross at (cx, cy); the axle rounds that corner on an arc
            double cx = arrival.isNorthSouth() ? x0 : wx;
            double cy = arrival.isNorthSouth() ? wy : y0;
            boolean left = exit == arrival.left();
            double r = left ? LEFT_TURN_RADIUS : RIGHT_TURN_RADIUS;
            // a car that entered late (the square right after another) has less room before the
            // lanes cross: it turns tighter, so it still ends on the exit lane's centre line
            double room = (cx - (x0 - arrival.dx() * axle)) * arrival.dx() + (cy - (y0 - arrival.dy() * axle)) * arrival.dy();
            r = Math.max(MIN_RADIUS, Math.min(r, room));
            double sx = cx - arrival.dx() * r;
            double sy = cy - arrival.dy() * r;
            path.straightTo(sx, sy);
            path.arc(sx + exit.dx() * r, sy + exit.dy() * r, r, left ? Math.PI / 2 : -Math.PI / 2);
            path.straightTo(endX, endY);
        }
        path.straightTo(wx + exit.dx() * (TAIL - axle), wy + exit.dy() * (TAIL - axle));
        return path.build();
    }

    /**
     * How far beyond the exit waypoint a crossing ends: half-way along the tail, where the car is
     * aligned with its lane — or at the waypoint itself when the next junction's square begins
     * before that, so the car can ask for that junction in time.
     */
    public static double finishBeyond(RoadNetwork network, Junction from, Compass exit, double wx, double wy) {
        Road road = Lanes.roadAlong(network, wx, wy, exit);
        if (road == null) {
            return TAIL / 2;
        }
        for (Junction j : network.junctions()) {
            if (j != from && road.carries(j.centre())) {
                double d = Lanes.distanceToSquare(j, exit, wx, wy);
                if (d > -Dimensions.JUNCTION_SIZE && d < TAIL / 2 + 1) {
                    return 0;
                }
            }
        }
        return TAIL / 2;
    }

    /**
     * The bearing to steer to for a car whose front is at ({@code x}, {@code y}), heading
     * {@code heading}, at {@code speed}: the plan is for its rear axle, which moves along its
     * heading, so the axle is steered. The nearest path point only moves on.
     */
    public double bearing(Vehicle car) {
        return bearing(car.x(), car.y(), car.headingDx(), car.headingDy(), car.speed());
    }

    /** The same for a front at ({@code x}, {@code y}) with the unit heading vector ({@code hx}, {@code hy}). */
    public double bearing(double x, double y, double hx, double hy, double speed) {
        return axleBearing(x - axle * hx, y - axle * hy, speed);
    }

    private double axleBearing(double x, double y, double speed) {
        if (isTurningOnTheSpot()) {
            int last = progress;
            while (last + 1 < onTheSpot.length && onTheSpot[last + 1]) {
                last++;
            }
            double next = headings[Math.min(progress + 1, last)];
            return next;
        }
        int nearest = progress;
        double best = Double.MAX_VALUE;
        for (int i = progress; i < Math.min(xs.length, progress + 16); i++) {
            if (i > progress && onTheSpot[i]) {
                break; // never skip a turn on the spot
            }
            double ex = xs[i] - x;
            double ey = ys[i] - y;
            double d = ex * ex + ey * ey; // squared: only compared
            if (d < best) {
                best = d;
                nearest = i;
            }
        }
        progress = nearest;
        // the heading planned a point ahead: on an arc, the nearest point's heading already lags
        int ahead = Math.min(nearest + 1, headings.length - 1);
        int planned = onTheSpot[ahead] ? nearest : ahead;
        double h = headings[planned];
        double hx = headingDx[planned];
        double hy = headingDy[planned];
        // how far the car is to the left of the path (left of a driver facing h is (cos h, -sin h))
        double left = (x - xs[nearest]) * hy - (y - ys[nearest]) * hx;
        return h - Math.toDegrees(Math.atan2(CROSS_TRACK_GAIN * left, speed + SOFTENING));
    }

    /** Whether the car has come to the path's last point. */
    public boolean isFinished() {
        return progress == xs.length - 1;
    }

    /** Whether the car is at a turn on the spot (it must stand still while it turns). */
    public boolean isTurningOnTheSpot() {
        return progress + 1 < onTheSpot.length && onTheSpot[progress + 1];
    }

    /** While turning on the spot: moves on once the car faces the next planned heading. */
    public void turned(double heading) {
        while (isTurningOnTheSpot() && Math.abs(Bearing.turn(heading, headings[progress + 1])) < TURNED) {
            progress++;
        }
    }

    /** Distance from the car's rear axle to the next turn on the spot ahead, or infinity. */
    public double distanceToTurnOnTheSpot(Vehicle car) {
        return distanceToTurnOnTheSpot(car.x(), car.y(), car.headingDx(), car.headingDy());
    }

    public double distanceToTurnOnTheSpot(double x, double y, double hx, double hy) {
        double px = x - axle * hx;
        double py = y - axle * hy;
        for (int i = progress; i + 1 < onTheSpot.length; i++) {
            if (onTheSpot[i + 1]) {
                return Math.hypot(xs[i] - px, ys[i] - py);
            }
        }
        return Double.POSITIVE_INFINITY;
    }

    /** Follows the rear axle along straights, arcs and turns on the spot and records where the front is. */
    private static final class Builder {
        private final double axle;
        private double[] xs = new double[128];
        private double[] ys = new double[128];
        private double[] hs = new double[128];
        private boolean[] spot = new boolean[128];
        private int n;
        private double ax;
        private double ay;
        private double heading;

        Builder(double axle) {
            this.axle = axle;
        }

        void start(double x, double y, double bearing) {
            ax = x;
            ay = y;
            heading = bearing;
            record(false);
        }

        void straightTo(double x, double y) {
            double fx = ax;
            double fy = ay;
            double length = Math.hypot(x - fx, y - fy);
            double direction = Bearing.between(fx, fy, x, y);
            if (length < MIN_STRAIGHT || Math.abs(Bearing.turn(heading, direction)) > 90) {
                // a sliver (the car a few millimetres off its lane centre) has no direction worth
                // steering by, and a car that entered late must not be sent back the way it came
                ax = x;
                ay = y;
                return;
            }
            heading = direction;
            int steps = Math.max(1, (int) Math.ceil(length / STEP));
            for (int i = 1; i <= steps; i++) {
                ax = fx + (x - fx) * i / steps;
                ay = fy + (y - fy) * i / steps;
                record(false);
            }
        }

        /** An arc about ({@code ox}, {@code oy}) of radius {@code r}, turning {@code sweep} radians (positive: left). */
        void arc(double ox, double oy, double r, double sweep) {
            double h0 = Math.toRadians(heading);
            int steps = (int) Math.round(ARC_STEPS * Math.abs(sweep) / (Math.PI / 2));
            double side = Math.signum(sweep);
            for (int i = 1; i <= steps; i++) {
                double h = h0 + sweep * i / steps;
                // the centre lies to the side the car turns towards
                ax = ox - Math.sin(h + side * Math.PI / 2) * r;
                ay = oy - Math.cos(h + side * Math.PI / 2) * r;
                heading = Bearing.normalise(Math.toDegrees(h));
                record(false);
            }
        }

        /** Turns on the spot to {@code bearing}, to the left or (U-turns in left-hand traffic) the right. */
        void turnOnTheSpot(double bearing, boolean toTheLeft) {
            double turn = Bearing.normalise(toTheLeft ? bearing - heading : heading - bearing);
            int steps = (int) Math.ceil(turn / ROTATION_STEP);
            double from = heading;
            for (int i = 1; i <= steps; i++) {
                heading = Bearing.normalise(from + (toTheLeft ? 1 : -1) * turn * i / steps);
                record(true);
            }
        }

        private void record(boolean onTheSpot) {
            if (n == xs.length) {
                xs = Arrays.copyOf(xs, 2 * n);
                ys = Arrays.copyOf(ys, 2 * n);
                hs = Arrays.copyOf(hs, 2 * n);
                spot = Arrays.copyOf(spot, 2 * n);
            }
            xs[n] = ax;
            ys[n] = ay;
            hs[n] = heading;
            spot[n] = onTheSpot;
            n++;
        }

        CrossingPath build() {
            return new CrossingPath(axle, Arrays.copyOf(xs, n), Arrays.copyOf(ys, n), Arrays.copyOf(hs, n),
                    Arrays.copyOf(spot, n));
        }
    }
}
