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
        return Math.hypot(x - other.x, y - other.y);
    }

    public double distanceTo(double ox, double oy) {
        return Math.hypot(x - ox, y - oy);
    }

    /** This point moved {@code distance} metres along {@code bearing} degrees. */
    public Vec2 moved(double bearing, double distance) {
        return new Vec2(x + distance * Bearing.dx(bearing), y + distance * Bearing.dy(bearing));
    }
}
