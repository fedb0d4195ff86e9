package sitcov.export;

import java.util.ArrayList;
import java.util.List;

/**
 * Which samples of a track become trajectory vertices. A player interpolates between vertices in
 * time; a sample is left out where that interpolation between the kept samples either side gives
 * its pose back within {@value #POSITION_TOLERANCE} m and {@value #HEADING_TOLERANCE_DEGREES}°.
 * Cars that stand or drive straight at a steady speed then cost two vertices, not one a tick,
 * and a replay stays within a millimetre of the run everywhere.
 */
final class KeptVertices {
    static final double POSITION_TOLERANCE = 0.001;
    static final double HEADING_TOLERANCE_DEGREES = 0.05;

    private KeptVertices() {
    }

    /** The indices of the samples to keep, in order; the first and last always. */
    static List<Integer> of(List<RunRecording.Sample> samples) {
        List<Integer> kept = new ArrayList<>();
        int anchor = 0;
        kept.add(0);
        int end = 1;
        while (end < samples.size()) {
            // grow the span from the anchor while every sample inside it is where interpolation puts it
            int next = end + 1;
            if (next < samples.size() && spans(samples, anchor, next)) {
                end = next;
                continue;
            }
            kept.add(end);
            anchor = end;
            end = anchor + 1;
        }
        return kept;
    }

    private static boolean spans(List<RunRecording.Sample> samples, int from, int to) {
        RunRecording.Sample a = samples.get(from);
        RunRecording.Sample b = samples.get(to);
        double turn = wrapped(b.bearing() - a.bearing());
        for (int i = from + 1; i < to; i++) {
            RunRecording.Sample s = samples.get(i);
            if (s.active() != a.active() || s.active() != b.active()) {
                return false;
            }
            double f = (double) (i - from) / (to - from);
            double x = a.x() + (b.x() - a.x()) * f;
            double y = a.y() + (b.y() - a.y()) * f;
            if (Math.hypot(s.x() - x, s.y() - y) > POSITION_TOLERANCE
                    || Math.abs(wrapped(s.bearing() - (a.bearing() + turn * f))) > HEADING_TOLERANCE_DEGREES) {
                return false;
            }
        }
        return a.active() == b.active();
    }

    /** An angle difference in degrees, brought into [−180, 180). */
    static double wrapped(double degrees) {
        return ((degrees % 360) + 540) % 360 - 180;
    }
}
