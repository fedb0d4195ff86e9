package sitcov.export;

import java.util.ArrayList;
import java.util.List;

/**
 * Which samples of a track become trajectory vertices, and the numbers written for them. A player places
 * a vehicle by its rear axle and interpolates linearly in time between vertices; a sample is left out
 * where that interpolation between the vertices either side, as written, gives back its rear axle and its
 * front within {@value #POSITION_TOLERANCE} m, and its heading within {@value #HEADING_TOLERANCE_DEGREES}°.
 * Both ends, so that the same holds for any point of the car a player interpolates (its footprint's centre
 * lies between them), and for a car that turns on the spot about its rear axle. Vertices are written to a
 * millimetre and a ten-thousandth of a radian, and the test is made on those rounded numbers, so that the
 * rounding counts against the tolerance instead of adding to it; the thinning keeps a tenth of a millimetre
 * of it back for the step a track writes after a turn on the spot (RecordedTrack). Cars that stand or drive
 * straight at a steady speed then cost two vertices, not one a tick.
 */
final class KeptVertices {
    static final double POSITION_TOLERANCE = 0.001;
    static final double HEADING_TOLERANCE_DEGREES = 0.05;
    /** Decimals of a vertex's position in metres: its millimetres. */
    static final int POSITION_DECIMALS = 3;
    /** Decimals of a vertex's heading in radians: 0.006°, a tenth of the tolerance. */
    static final int HEADING_DECIMALS = 4;
    private static final double POSITION_UNIT = 1e-3;
    private static final double HEADING_UNIT = 1e-4;
    private static final double HEADING_TOLERANCE = Math.toRadians(HEADING_TOLERANCE_DEGREES);
    /** What the thinning leaves to a turn on the spot: a vertex may be nudged a tenth of a millimetre. */
    private static final double THINNED_TOLERANCE = POSITION_TOLERANCE - POSITION_UNIT / 10;

    private KeptVertices() {
    }

    /**
     * A vertex as written: the index of its sample, and its rear axle in the ASAM frame as whole
     * millimetres and its heading as whole ten-thousandths of a radian, in (−π, π].
     */
    record Vertex(int sample, long x, long y, long h) {
        /**
         * Its WorldPosition, written with the numbers the thinning tested, but for x given in tenths of a
         * millimetre ({@link #NUDGES_A_UNIT} to the unit): where the track nudges a vertex a tenth east.
         */
        void position(Xml xml, long xTenths) {
            xml.open("Position");
            xml.empty("WorldPosition", "x", Xml.decimal(xTenths, POSITION_DECIMALS + 1), "y",
                    Xml.decimal(y, POSITION_DECIMALS), "h", Xml.decimal(h, HEADING_DECIMALS));
            xml.close();
        }
    }

    /** Tenths of a millimetre in a millimetre: the step of a nudge, within the position's tolerance. */
    static final long NUDGES_A_UNIT = 10;

    /** The vertices of {@code kind}'s track, in order; its first and last sample always. */
    static List<Vertex> of(List<RunRecording.Sample> samples, ScenarioParts.Kind kind) {
        Track t = new Track(samples, kind);
        int n = samples.size();
        List<Vertex> kept = new ArrayList<>();
        kept.add(t.vertex(0));
        int anchor = 0;
        while (anchor < n - 1) {
            // the span from the anchor is stretched by doubling, then narrowed by halving: a car that stands
            // for a thousand ticks costs a few dozen tests of its span, not a thousand
            int good = anchor + 1;
            int bad = n;
            for (int step = 2; anchor + step < n; step *= 2) {
                if (!t.spans(anchor, anchor + step)) {
                    bad = anchor + step;
                    break;
                }
                good = anchor + step;
            }
            if (bad == n && good < n - 1 && t.spans(anchor, n - 1)) {
                good = n - 1;
            }
            while (bad - good > 1 && good < n - 1) {
                int middle = (good + bad) >>> 1;
                if (t.spans(anchor, middle)) {
                    good = middle;
                } else {
                    bad = middle;
                }
            }
            kept.add(t.vertex(good));
            anchor = good;
        }
        return kept;
    }

    /** A track's rear-axle poses and fronts in the ASAM frame, exact and as a vertex would write them. */
    private static final class Track {
        private final double rearAxleBehindFront;
        private final boolean[] active;
        private final double[] x;
        private final double[] y;
        private final double[] h;
        private final double[] frontX;
        private final double[] frontY;
        private final long[] writtenX;
        private final long[] writtenY;
        private final long[] writtenH;

        Track(List<RunRecording.Sample> samples, ScenarioParts.Kind kind) {
            int n = samples.size();
            rearAxleBehindFront = kind.rearAxleBehindFront();
            active = new boolean[n];
            frontX = new double[n];
            frontY = new double[n];
            x = new double[n];
            y = new double[n];
            h = new double[n];
            writtenX = new long[n];
            writtenY = new long[n];
            writtenH = new long[n];
            for (int i = 0; i < n; i++) {
                RunRecording.Sample s = samples.get(i);
                active[i] = s.active();
                x[i] = AsamFrame.x(kind.rearAxleX(s.x(), s.bearing()));
                y[i] = AsamFrame.y(kind.rearAxleY(s.y(), s.bearing()));
                h[i] = AsamFrame.heading(s.bearing());
                frontX[i] = AsamFrame.x(s.x());
                frontY[i] = AsamFrame.y(s.y());
                writtenX[i] = Math.round(x[i] / POSITION_UNIT);
                writtenY[i] = Math.round(y[i] / POSITION_UNIT);
                writtenH[i] = heading(h[i]);
            }
        }

        /** A heading in whole units, kept in (−π, π] where rounding would carry it past π. */
        private static long heading(double radians) {
            long units = Math.round(radians / HEADING_UNIT);
            if (units * HEADING_UNIT > Math.PI) {
                units--;
            } else if (units * HEADING_UNIT <= -Math.PI) {
                units++;
            }
            return units;
        }

        Vertex vertex(int i) {
            return new Vertex(i, writtenX[i], writtenY[i], writtenH[i]);
        }

        boolean spans(int from, int to) {
            if (active[from] != active[to]) {
                return false;
            }
            double ax = writtenX[from] * POSITION_UNIT;
            double ay = writtenY[from] * POSITION_UNIT;
            double ah = writtenH[from] * HEADING_UNIT;
            double dx = writtenX[to] * POSITION_UNIT - ax;
            double dy = writtenY[to] * POSITION_UNIT - ay;
            double bh = writtenH[to] * HEADING_UNIT;
            double turn = Math.IEEEremainder(bh - ah, 2 * Math.PI);
            // the fronts the written vertices place, ahead of their rear axles
            double afx = ax + Math.cos(ah) * rearAxleBehindFront;
            double afy = ay + Math.sin(ah) * rearAxleBehindFront;
            double dfx = ax + dx + Math.cos(bh) * rearAxleBehindFront - afx;
            double dfy = ay + dy + Math.sin(bh) * rearAxleBehindFront - afy;
            for (int i = from + 1; i < to; i++) {
                double f = (double) (i - from) / (to - from);
                if (active[i] != active[from]
                        || Math.hypot(x[i] - (ax + dx * f), y[i] - (ay + dy * f)) > THINNED_TOLERANCE
                        || Math.hypot(frontX[i] - (afx + dfx * f), frontY[i] - (afy + dfy * f)) > THINNED_TOLERANCE
                        || Math.abs(Math.IEEEremainder(h[i] - (ah + turn * f), 2 * Math.PI)) > HEADING_TOLERANCE) {
                    return false;
                }
            }
            return true;
        }
    }
}
