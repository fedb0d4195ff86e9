package sitcov.builtin;

import sitcov.geom.Compass;
import sitcov.sensors.LaneEstimate;
import sitcov.vehicles.Lanes;

/**
 * Where the car last saw its lane centre line, kept as a coordinate across the road, so that in
 * a tick with no marking in sight (pulled out at an angle, or the lines cut at a junction) it
 * still knows where its lane is instead of assuming it is centred in it. Forgotten when the lane
 * direction changes.
 */
final class LaneMemory {
    private Compass lane;
    private double line = Double.NaN;

    /** The lane centre's offset to the right of the car at ({@code x}, {@code y}), seen now or remembered. */
    double laneCentre(Compass direction, double x, double y, LaneEstimate seen) {
        if (direction != lane) {
            lane = direction;
            line = Double.NaN;
        }
        double across = direction.isNorthSouth() ? x : y;
        int right = Lanes.rightSign(direction);
        if (seen.anySeen()) {
            line = across + right * seen.laneCentre();
            return seen.laneCentre();
        }
        return Double.isNaN(line) ? 0 : (line - across) * right;
    }
}
