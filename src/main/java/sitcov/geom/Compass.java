package sitcov.geom;

/** The four axis directions, with the bearing of each (north is −y). */
public enum Compass {
    NORTH(180, 0, -1),
    EAST(90, 1, 0),
    SOUTH(0, 0, 1),
    WEST(270, -1, 0);

    private final double bearing;
    private final int dx;
    private final int dy;

    Compass(double bearing, int dx, int dy) {
        this.bearing = bearing;
        this.dx = dx;
        this.dy = dy;
    }

    public double bearing() {
        return bearing;
    }

    /** The x step of a unit move this way: −1, 0 or 1. */
    /** values() copies its array on every call; turning is asked for every tick. */
    private static final Compass[] ALL = values();

    public int dx() {
        return dx;
    }

    /** The y step of a unit move this way: −1, 0 or 1. */
    public int dy() {
        return dy;
    }

    public Compass opposite() {
        return ALL[(ordinal() + 2) % 4];
    }

    /** The direction 90° to the left for a driver heading this way. */
    public Compass left() {
        return ALL[(ordinal() + 3) % 4];
    }

    /** The direction 90° to the right for a driver heading this way. */
    public Compass right() {
        return ALL[(ordinal() + 1) % 4];
    }

    public boolean isNorthSouth() {
        return dx == 0;
    }

    /** The compass direction nearest {@code bearing}; ties go clockwise-first as in the original (45 → EAST). */
    public static Compass nearest(double bearing) {
        double b = Bearing.normalise(bearing);
        if (b >= 315 || b < 45) {
            return SOUTH;
        }
        if (b < 135) {
            return EAST;
        }
        if (b < 225) {
            return NORTH;
        }
        return WEST;
    }

    /** The direction with exactly this bearing (0, 90, 180 or 270). */
    public static Compass ofBearing(double bearing) {
        double b = Bearing.normalise(bearing);
        for (Compass c : values()) {
            if (c.bearing == b) {
                return c;
            }
        }
        throw new IllegalArgumentException("bearing " + bearing + " is not one of 0, 90, 180, 270");
    }
}
