package sitcov.builtin;

import sitcov.geom.Compass;

/**
 * Coordinates relative to the car in the frame of its lane: {@code u} metres ahead along the
 * lane direction, {@code v} metres to its right.
 */
final class LaneFrame {
    private LaneFrame() {
    }

    static double u(Compass lane, double fromX, double fromY, double x, double y) {
        return (x - fromX) * lane.dx() + (y - fromY) * lane.dy();
    }

    static double v(Compass lane, double fromX, double fromY, double x, double y) {
        Compass right = lane.right();
        return (x - fromX) * right.dx() + (y - fromY) * right.dy();
    }

    static double x(Compass lane, double fromX, double u, double v) {
        return fromX + u * lane.dx() + v * lane.right().dx();
    }

    static double y(Compass lane, double fromY, double u, double v) {
        return fromY + u * lane.dy() + v * lane.right().dy();
    }
}
