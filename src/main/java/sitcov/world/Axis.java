package sitcov.world;

import sitcov.geom.Compass;

/** The orientation of a straight road. */
public enum Axis {
    NORTH_SOUTH,
    EAST_WEST;

    /** The bearing of a parked car's long side on a road of this axis. */
    public double bearing() {
        return this == NORTH_SOUTH ? 0 : 90;
    }

    public Axis other() {
        return this == NORTH_SOUTH ? EAST_WEST : NORTH_SOUTH;
    }

    public static Axis of(Compass direction) {
        return direction.isNorthSouth() ? NORTH_SOUTH : EAST_WEST;
    }
}
