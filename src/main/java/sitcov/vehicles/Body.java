package sitcov.vehicles;

import sitcov.geom.Bearing;
import sitcov.geom.Box;

/**
 * The kinematic state of a car: front-centre position, heading and speed, changed only by the
 * shared dynamics (at most one speed change and one capped turn a tick, then a move). A car turns
 * about its rear axle, {@code pivot} metres behind its front, as a real car does: its body
 * follows the inside of a bend rather than swinging its tail out across the kerb.
 */
public final class Body {
    private double pivot;
    private double x;
    private double y;
    private double heading;
    /** The unit vector along the heading, kept with it: most of a tick's geometry needs it. */
    private double headingDx;
    private double headingDy;
    private double speed;
    /** The footprint last handed out, while the body has not moved since: most ticks ask for it many times. */
    private Box footprint;

    public Body(double x, double y, double heading, double pivot) {
        this.pivot = pivot;
        this.x = x;
        this.y = y;
        setHeading(heading);
    }

    private void setHeading(double bearing) {
        heading = Bearing.normalise(bearing);
        headingDx = Bearing.dx(heading);
        headingDy = Bearing.dy(heading);
    }

    public double x() {
        return x;
    }

    public double y() {
        return y;
    }

    public double heading() {
        return heading;
    }

    public double headingDx() {
        return headingDx;
    }

    public double headingDy() {
        return headingDy;
    }

    public double speed() {
        return speed;
    }

    /** Its footprint ({@code length} by {@code width}, trailing its front centre); the same object until it moves. */
    Box footprint(double length, double width) {
        if (footprint == null || footprint.length() != length || footprint.width() != width) {
            footprint = Box.behind(x, y, heading, headingDx, headingDy, length, width);
        }
        return footprint;
    }

    void place(double nx, double ny, double nheading) {
        footprint = null;
        x = nx;
        y = ny;
        setHeading(nheading);
        speed = 0;
    }

    /**
     * Takes on the pose and speed the world reports (a controller's model of its own car): the
     * heading is taken as it comes, already normalised, so its unit vector is the world's to the bit.
     */
    public void sync(double nx, double ny, double nheading, double nspeed) {
        if (nx != x || ny != y || nheading != heading) {
            footprint = null;
            x = nx;
            y = ny;
            heading = nheading;
            headingDx = Bearing.dx(heading);
            headingDy = Bearing.dy(heading);
        }
        speed = nspeed;
    }

    /** Sets the speed (already within the car's limits). */
    void setSpeed(double v) {
        speed = v;
    }

    public void accelerate() {
        speed = Math.min(Dynamics.MAX_SPEED, speed + Dynamics.ACCELERATION);
    }

    public void brake() {
        speed = Math.max(0, speed - Dynamics.BRAKING);
    }

    void stop() {
        speed = 0;
    }

    /** One tick's speed change towards {@code target}: accelerate, brake or hold, never overshooting by more than one step. */
    public void approachSpeed(double target) {
        speed = speedAfter(target);
    }

    private double speedAfter(double target) {
        if (speed > target + 1e-9) {
            return Math.max(0, speed - Dynamics.BRAKING);
        } else if (speed + Dynamics.ACCELERATION <= target + 1e-9) {
            return Math.min(Dynamics.MAX_SPEED, speed + Dynamics.ACCELERATION);
        }
        return Math.max(speed, target);
    }

    /**
     * The footprint ({@code length} by {@code width}) this body would have after one tick of
     * {@link #approachSpeed}, {@link #turnTowards} and {@link #move}, leaving the body as it is,
     * stretched forward by the distance it would then need to stop.
     */
    Box reachAfter(double targetSpeed, double bearing, double maxTurn, double length, double width) {
        double turn = Math.max(-maxTurn, Math.min(maxTurn, Bearing.turn(heading, bearing)));
        double h = Bearing.normalise(heading + turn);
        // an unturned heading normalises to itself, so its kept vector is the turned one's
        double hx = h == heading ? headingDx : Bearing.dx(h);
        double hy = h == heading ? headingDy : Bearing.dy(h);
        double nx = x - pivot * headingDx + pivot * hx;
        double ny = y - pivot * headingDy + pivot * hy;
        double v = speedAfter(targetSpeed);
        double reach = v + Math.max(0, Dynamics.stoppingDistance(v) - v);
        return Box.behind(nx + reach * hx, ny + reach * hy, h, hx, hy, length + reach - v, width);
    }

    /** Turns towards {@code bearing} by at most {@code maxTurn} degrees. */
    public void turnTowards(double bearing, double maxTurn) {
        turnBy(turnTowards(heading, bearing, maxTurn));
    }

    /** The turn from {@code heading} towards {@code bearing}, at most {@code maxTurn} degrees either way. */
    public static double turnTowards(double heading, double bearing, double maxTurn) {
        double turn = Bearing.turn(heading, bearing);
        return Math.max(-maxTurn, Math.min(maxTurn, turn));
    }

    /** Turns by {@code turn} degrees (already within the car's limit) about the pivot. */
    void turnBy(double turn) {
        if (turn == 0) {
            return;
        }
        double px = x - pivot * headingDx;
        double py = y - pivot * headingDy;
        footprint = null;
        setHeading(heading + turn);
        x = px + pivot * headingDx;
        y = py + pivot * headingDy;
    }

    /** Moves one tick along the heading at the current speed. */
    public void move() {
        if (speed != 0) {
            footprint = null;
        }
        x += speed * headingDx;
        y += speed * headingDy;
    }
}
