package sitcov.vehicles;

import sitcov.geom.Bearing;
import sitcov.geom.Box;

/**
 * The kinematic state of a car: front-centre position, heading and speed, changed only by the
 * shared dynamics (at most one speed change and one capped turn a tick, then a move). A car turns
 * about its rear axle, {@code pivot} metres behind its front, as a real car does: its body
 * follows the inside of a bend rather than swinging its tail out across the kerb.
 */
final class Body {
    private final double pivot;
    private double x;
    private double y;
    private double heading;
    private double speed;
    /** The footprint last handed out, while the body has not moved since: most ticks ask for it many times. */
    private Box footprint;

    Body(double x, double y, double heading, double pivot) {
        this.pivot = pivot;
        this.x = x;
        this.y = y;
        this.heading = Bearing.normalise(heading);
    }

    double x() {
        return x;
    }

    double y() {
        return y;
    }

    double heading() {
        return heading;
    }

    double speed() {
        return speed;
    }

    /** Its footprint ({@code length} by {@code width}, trailing its front centre); the same object until it moves. */
    Box footprint(double length, double width) {
        if (footprint == null || footprint.length() != length || footprint.width() != width) {
            footprint = Box.behind(x, y, heading, length, width);
        }
        return footprint;
    }

    void place(double nx, double ny, double nheading) {
        footprint = null;
        x = nx;
        y = ny;
        heading = Bearing.normalise(nheading);
        speed = 0;
    }

    void accelerate() {
        speed = Math.min(Dynamics.MAX_SPEED, speed + Dynamics.ACCELERATION);
    }

    void brake() {
        speed = Math.max(0, speed - Dynamics.BRAKING);
    }

    void stop() {
        speed = 0;
    }

    /** One tick's speed change towards {@code target}: accelerate, brake or hold, never overshooting by more than one step. */
    void approachSpeed(double target) {
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
        double nx = x - pivot * Bearing.dx(heading) + pivot * Bearing.dx(h);
        double ny = y - pivot * Bearing.dy(heading) + pivot * Bearing.dy(h);
        double v = speedAfter(targetSpeed);
        double reach = v + Math.max(0, Dynamics.stoppingDistance(v) - v);
        double r = Math.toRadians(h);
        return Box.behind(nx + reach * Math.sin(r), ny + reach * Math.cos(r), h, length + reach - v, width);
    }

    /** Turns towards {@code bearing} by at most {@code maxTurn} degrees. */
    void turnTowards(double bearing, double maxTurn) {
        double turn = Bearing.turn(heading, bearing);
        turn = Math.max(-maxTurn, Math.min(maxTurn, turn));
        if (turn == 0) {
            return;
        }
        double px = x - pivot * Bearing.dx(heading);
        double py = y - pivot * Bearing.dy(heading);
        footprint = null;
        heading = Bearing.normalise(heading + turn);
        x = px + pivot * Bearing.dx(heading);
        y = py + pivot * Bearing.dy(heading);
    }

    /** Moves one tick along the heading at the current speed. */
    void move() {
        if (speed != 0) {
            footprint = null;
        }
        double r = Math.toRadians(heading);
        x += speed * Math.sin(r);
        y += speed * Math.cos(r);
    }
}
