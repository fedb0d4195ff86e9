package sitcov.export;

import sitcov.world.Dimensions;

/**
 * sitcov's coordinates in the ASAM formats' frame. sitcov measures y southwards (a picture's
 * rows) and bearings clockwise from south; OpenDRIVE and OpenSCENARIO are right-handed, y
 * northwards and headings anticlockwise from east. Mirroring y alone would swap left for right and
 * so turn left-hand traffic into right-hand: y is measured up from the world's southern edge
 * instead, which keeps every coordinate of the 200 m × 100 m world positive.
 */
public final class AsamFrame {
    private AsamFrame() {
    }

    public static double x(double sitcovX) {
        return sitcovX;
    }

    public static double y(double sitcovY) {
        return Dimensions.WORLD_HEIGHT - sitcovY;
    }

    /** A sitcov bearing (degrees; 0 south, 90 east, 180 north) as an ASAM heading, radians in (−π, π]. */
    public static double heading(double bearingDegrees) {
        double degrees = Math.IEEEremainder(bearingDegrees - 90, 360);
        return Math.toRadians(degrees == -180 ? 180 : degrees);
    }

    /** When the state after {@code tick} holds: the start is at 0 s and tick 0 ends at one tick's length. */
    public static double seconds(long tick) {
        return (tick + 1) * Dimensions.TICK_SECONDS;
    }
}
