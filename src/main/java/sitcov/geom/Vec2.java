package sitcov.geom;

/** A point or displacement in the plane, in metres. */
public record Vec2(double x, double y) {
    public static final Vec2 ZERO = new Vec2(0, 0);

    public Vec2 plus(Vec2 other) {
        return new Vec2(x + other.x, y + other.y);
    }

    public Vec2 minus(Vec2 other) {
        return new Vec2(x - other.x, y - other.y);
    }

    public Vec2 times(double factor) {
        return new Vec2(x * factor, y * factor);
    }

    public double length() {
        return Math.hypot(x, y);
    }

    public double distanceTo(Vec2 other) {
        return distanceTo(other.x, other.y);
    }

    public double distanceTo(double ox, double oy) {
        double dx = x - ox;
        double dy = y - oy;
        return Math.sqrt(dx * dx + dy * dy); // not hypot: far slower, and no overflow is possible here
    }

    /** This point moved {@code distance} metres along {@code bearing} degrees. */
    public Vec2 moved(double bearing, double distance) {
        return new Vec2(x + distance * Bearing.dx(bearing), y + distance * Bearing.dy(bearing));
    }
}
