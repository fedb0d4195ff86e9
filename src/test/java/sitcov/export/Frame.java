package sitcov.export;

import sitcov.geom.Bearing;
import sitcov.geom.Compass;
import sitcov.geom.Vec2;
import sitcov.world.Dimensions;

/**
 * sitcov's world frame as OpenDRIVE and OpenSCENARIO see it (src/main/java/sitcov/export/README.md, "The frame"): x
 * stays,
 * y = 100 − sitcov y (sitcov's y grows southwards), heading counter-clockwise from +x in radians.
 */
final class Frame {
    /** How close an exported position must be to sitcov's: a centimetre. */
    static final double METRE_TOLERANCE = 0.01;
    /** How close an exported heading must be to sitcov's, in radians (2.5 mm across a car's half length). */
    static final double HEADING_TOLERANCE = 1e-3;

    private Frame() {
    }

    static Vec2 point(Vec2 sitcov) {
        return new Vec2(sitcov.x(), Dimensions.WORLD_HEIGHT - sitcov.y());
    }

    static Vec2 point(double x, double y) {
        return point(new Vec2(x, y));
    }

    /** The exported heading of a sitcov bearing, in (−π, π]. */
    static double heading(double bearing) {
        double h = Math.toRadians(Bearing.normalise(bearing - 90));
        return h > Math.PI ? h - 2 * Math.PI : h;
    }

    /** The unit vector of a compass direction in the exported frame. */
    static Vec2 direction(Compass c) {
        return new Vec2(c.dx(), -c.dy());
    }

    static Vec2 unit(double heading) {
        return new Vec2(Math.cos(heading), Math.sin(heading));
    }

    /** The difference of two headings, in [0, π]. */
    static double angleBetween(double a, double b) {
        double d = Math.abs(Math.IEEEremainder(a - b, 2 * Math.PI));
        return Math.min(d, 2 * Math.PI - d);
    }
}
