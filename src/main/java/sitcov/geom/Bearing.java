package sitcov.geom;

/**
 * Bearings in degrees, measured from +y (south) towards +x (east): 0 south, 90 east, 180 north,
 * 270 west. Increasing the bearing is a left turn for a driver.
 */
public final class Bearing {
    /** cos and sin of the whole quarter turns from −360° to 360°, by the very expressions {@link #cos} and {@link #sin} stand for. */
    private static final double[] QUARTER_COS = new double[9];
    private static final double[] QUARTER_SIN = new double[9];

    static {
        for (int q = -4; q <= 4; q++) {
            QUARTER_COS[q + 4] = Math.cos(Math.toRadians(q * 90.0));
            QUARTER_SIN[q + 4] = Math.sin(Math.toRadians(q * 90.0));
        }
    }

    private Bearing() {
    }

    /**
     * {@code Math.cos(Math.toRadians(degrees))}, to the bit; looked up when {@code degrees} is a
     * whole quarter turn, as two cars' headings on straight roads mostly differ by.
     */
    public static double cos(double degrees) {
        int whole = (int) degrees;
        if (whole == degrees && whole % 90 == 0 && whole >= -360 && whole <= 360) {
            return QUARTER_COS[whole / 90 + 4];
        }
        return Math.cos(Math.toRadians(degrees));
    }

    /** {@code Math.sin(Math.toRadians(degrees))}, to the bit (the sign of a zero kept); looked up like {@link #cos}. */
    public static double sin(double degrees) {
        if (degrees == 0) {
            return Math.sin(Math.toRadians(degrees));
        }
        int whole = (int) degrees;
        if (whole == degrees && whole % 90 == 0 && whole >= -360 && whole <= 360) {
            return QUARTER_SIN[whole / 90 + 4];
        }
        return Math.sin(Math.toRadians(degrees));
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
