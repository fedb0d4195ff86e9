package sitcov.geom;

/**
 * Bearings in degrees, measured from +y (south) towards +x (east): 0 south, 90 east, 180 north,
 * 270 west. Increasing the bearing is a left turn for a driver.
 */
public final class Bearing {
    private Bearing() {
    }

    /** The x component of a unit move along {@code bearing}. */
    public static double dx(double bearing) {
        return Math.sin(Math.toRadians(bearing));
    }

    /** The y component of a unit move along {@code bearing}. */
    public static double dy(double bearing) {
        return Math.cos(Math.toRadians(bearing));
    }

    /** {@code bearing} brought into [0, 360). */
    public static double normalise(double bearing) {
        double b = bearing % 360.0;
        if (b < 0) {
            b += 360.0;
        }
        return b == 360.0 ? 0.0 : b;
    }

    /** The bearing from ({@code fromX}, {@code fromY}) to ({@code toX}, {@code toY}), in [0, 360). */
    public static double between(double fromX, double fromY, double toX, double toY) {
        return normalise(Math.toDegrees(Math.atan2(toX - fromX, toY - fromY)));
    }

    public static double between(Vec2 from, Vec2 to) {
        return between(from.x(), from.y(), to.x(), to.y());
    }

    /** The signed turn from {@code from} to {@code to} in (−180, 180]; positive is a left turn. */
    public static double turn(double from, double to) {
        double d = normalise(to - from);
        return d > 180.0 ? d - 360.0 : d;
    }
}
