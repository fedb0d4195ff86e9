package sitcov.geom;

/** Ray tests for sensors: exact intervals, and the sampled sensor semantics built on them. */
public final class Rays {
    private Rays() {
    }

    /**
     * The slab test in a box's own frame: the ray starts at offsets (p, q) from the centre and
     * moves (dp, dq) per metre; half sizes (hp, hq). Writes [entry, exit] (entry may be negative
     * when the ray starts inside) and returns whether the ray meets the box ahead.
     */
    static boolean slabs(double p, double dp, double hp, double q, double dq, double hq, double[] out) {
        double t0 = Double.NEGATIVE_INFINITY;
        double t1 = Double.POSITIVE_INFINITY;
        if (dp == 0) {
            if (Math.abs(p) > hp) {
                return false;
            }
        } else {
            double a = (-hp - p) / dp;
            double b = (hp - p) / dp;
            t0 = Math.min(a, b);
            t1 = Math.max(a, b);
        }
        if (dq == 0) {
            if (Math.abs(q) > hq) {
                return false;
            }
        } else {
            double a = (-hq - q) / dq;
            double b = (hq - q) / dq;
            t0 = Math.max(t0, Math.min(a, b));
            t1 = Math.min(t1, Math.max(a, b));
        }
        if (t0 > t1 || t1 < 0) {
            return false;
        }
        out[0] = t0;
        out[1] = t1;
        return true;
    }

    /**
     * The first sample of a sampled ray that falls in [{@code entry}, {@code exit}]: samples lie at
     * {@code start + k·step} for k = 1, 2, … up to {@code limit}. Returns its distance, or NaN when
     * every sample misses (a thin strip can fall between two samples).
     */
    public static double firstSample(double entry, double exit, double start, double step, double limit) {
        double k = Math.max(1, Math.ceil((entry - start) / step - 1e-9));
        double d = start + k * step;
        return d <= exit + 1e-9 && d <= limit + 1e-9 ? d : Double.NaN;
    }
}
