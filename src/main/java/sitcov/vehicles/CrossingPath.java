package sitcov.vehicles;

import java.util.Arrays;
import sitcov.geom.Compass;

/**
 * The path of the car's front through a junction square, from where it entered to its exit
 * waypoint and a short straight beyond. The car turns about its rear axle, so the path is planned
 * for the axle: straight to where the incoming and outgoing lane centres cross, a turn there, and
 * straight out (a half circle across the road for a U-turn); the front's path is the axle's moved
 * forward by the axle distance. The car follows it by pure pursuit, steering at the path point a
 * short lookahead ahead.
 */
final class CrossingPath {
    static final double LOOKAHEAD = 1.5;
    /** The path runs on this far beyond the waypoint, along the exit lane, so the car leaves aligned. */
    static final double TAIL = 4.0;
    /**
     * Radii of the rear axle's arc. A left turn (the near side) curves round the kerb corner itself,
     * so the body's inside keeps 0.5 m off it; a right turn is wide enough that the front's outer
     * corner stays on the road; a U-turn half circle is centred on the road's centre line.
     */
    static final double LEFT_TURN_RADIUS = 1.5;
    static final double RIGHT_TURN_RADIUS = 2.5;
    static final double U_TURN_RADIUS = 1.5;
    private static final int ARC_STEPS = 12;
    private static final double STEP = 0.5;

    private final double[] xs;
    private final double[] ys;
    private int progress;

    private CrossingPath(double[] xs, double[] ys) {
        this.xs = xs;
        this.ys = ys;
    }

    /**
     * The path for a car whose front is at ({@code x0}, {@code y0}) arriving {@code arrival}, to
     * the waypoint, leaving {@code exit}; the rear axle is {@code axle} metres behind the front.
     */
    static CrossingPath between(double x0, double y0, Compass arrival, double wx, double wy, Compass exit, double axle) {
        Builder front = new Builder(axle);
        double px = x0 - arrival.dx() * axle;
        double py = y0 - arrival.dy() * axle;
        front.start(px, py, arrival);
        if (exit == arrival) {
            front.straight(wx - exit.dx() * axle, wy - exit.dy() * axle, exit);
        } else if (exit == arrival.opposite()) {
            Compass right = arrival.right();
            front.arc(px + right.dx() * U_TURN_RADIUS, py + right.dy() * U_TURN_RADIUS, U_TURN_RADIUS, arrival, -Math.PI);
            front.straight(wx - exit.dx() * axle, wy - exit.dy() * axle, exit);
        } else {
            // the lane centres cross at (cx, cy); the axle rounds that corner on an arc
            double cx = arrival.isNorthSouth() ? x0 : wx;
            double cy = arrival.isNorthSouth() ? wy : y0;
            boolean left = exit == arrival.left();
            double r = left ? LEFT_TURN_RADIUS : RIGHT_TURN_RADIUS;
            front.straight(cx - arrival.dx() * r, cy - arrival.dy() * r, arrival);
            front.arc(cx - arrival.dx() * r + exit.dx() * r, cy - arrival.dy() * r + exit.dy() * r, r, arrival,
                    left ? Math.PI / 2 : -Math.PI / 2);
            front.straight(wx - exit.dx() * axle, wy - exit.dy() * axle, exit);
        }
        front.straight(wx + exit.dx() * (TAIL - axle), wy + exit.dy() * (TAIL - axle), exit);
        return front.build();
    }

    /** The path point to steer at from ({@code x}, {@code y}): the last one within the lookahead, moving on only. */
    double[] aim(double x, double y) {
        int nearest = progress;
        double best = Double.MAX_VALUE;
        for (int i = progress; i < Math.min(xs.length, progress + 12); i++) {
            double d = Math.hypot(xs[i] - x, ys[i] - y);
            if (d < best) {
                best = d;
                nearest = i;
            }
        }
        progress = nearest;
        int target = nearest;
        while (target + 1 < xs.length && Math.hypot(xs[target + 1] - x, ys[target + 1] - y) <= LOOKAHEAD) {
            target++;
        }
        if (target == nearest && target + 1 < xs.length) {
            target++;
        }
        return new double[] {xs[target], ys[target]};
    }

    /**
     * Follows the rear axle along straights and arcs and records where the front is: the axle's
     * position moved forward along its heading.
     */
    private static final class Builder {
        private final double axle;
        private double[] xs = new double[128];
        private double[] ys = new double[128];
        private int n;
        private double ax;
        private double ay;

        Builder(double axle) {
            this.axle = axle;
        }

        void start(double x, double y, Compass heading) {
            ax = x;
            ay = y;
            record(heading.dx(), heading.dy());
        }

        void straight(double x, double y, Compass heading) {
            double fx = ax;
            double fy = ay;
            int steps = Math.max(1, (int) Math.ceil(Math.hypot(x - fx, y - fy) / STEP));
            for (int i = 1; i <= steps; i++) {
                ax = fx + (x - fx) * i / steps;
                ay = fy + (y - fy) * i / steps;
                record(heading.dx(), heading.dy());
            }
        }

        /**
         * An arc about ({@code ox}, {@code oy}) of radius {@code r}, starting heading {@code from},
         * turning {@code sweep} radians (positive: to the left, as bearings count).
         */
        void arc(double ox, double oy, double r, Compass from, double sweep) {
            double heading0 = Math.toRadians(from.bearing());
            for (int i = 1; i <= ARC_STEPS * Math.abs(sweep) / (Math.PI / 2); i++) {
                double h = heading0 + sweep * i / (ARC_STEPS * Math.abs(sweep) / (Math.PI / 2));
                double hx = Math.sin(h);
                double hy = Math.cos(h);
                // the centre lies to the side the car turns towards
                double side = Math.signum(sweep);
                double lx = Math.sin(h + side * Math.PI / 2);
                double ly = Math.cos(h + side * Math.PI / 2);
                ax = ox - lx * r;
                ay = oy - ly * r;
                record(hx, hy);
            }
        }

        private void record(double hx, double hy) {
            if (n == xs.length) {
                xs = Arrays.copyOf(xs, 2 * n);
                ys = Arrays.copyOf(ys, 2 * n);
            }
            xs[n] = ax + hx * axle;
            ys[n] = ay + hy * axle;
            n++;
        }

        CrossingPath build() {
            return new CrossingPath(Arrays.copyOf(xs, n), Arrays.copyOf(ys, n));
        }
    }
}
