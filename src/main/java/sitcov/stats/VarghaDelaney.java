package sitcov.stats;

/**
 * Vargha and Delaney's Â12 effect size (Vargha &amp; Delaney 2000, "A critique and improvement of the
 * CL common language effect size statistics of McGraw and Wong", Journal of Educational and
 * Behavioral Statistics 25:101): the probability that a value drawn from the first sample exceeds
 * one drawn from the second, ties counting one half, Â12 = P(X &gt; Y) + ½·P(X = Y). It is the
 * Mann-Whitney U of the first sample scaled by mn, and the effect size that Arcuri &amp; Briand (2011,
 * ICSE, "A practical guide for using statistical tests to assess randomized algorithms in software
 * engineering") recommend to report beside the U test's p-value.
 */
public final class VarghaDelaney {
    private VarghaDelaney() {
    }

    /**
     * Â12 of {@code x} over {@code y}; 0.5 means neither tends to be larger. NaN when either sample is
     * empty: there is no pair to count (a shard or a folder with no replications still gets its tables).
     */
    public static double a12(double[] x, double[] y) {
        if (x.length == 0 || y.length == 0) {
            return Double.NaN;
        }
        // Direct pair counting: O(mn), exact in rational arithmetic up to the one final division.
        long twiceWins = 0;
        for (double xi : x) {
            for (double yj : y) {
                if (Double.isNaN(xi) || Double.isNaN(yj)) {
                    throw new IllegalArgumentException("NaN cannot be compared");
                }
                twiceWins += xi > yj ? 2 : xi == yj ? 1 : 0;
            }
        }
        return twiceWins / (2.0 * x.length * y.length);
    }

    /**
     * Vargha &amp; Delaney's (2000) labels: Â12 ≥ 0.71 (or ≤ 0.29) large, ≥ 0.64 (≤ 0.36)
     * medium, ≥ 0.56 (≤ 0.44) small, anything nearer 0.5 negligible. The thresholds are compared
     * with Â12 itself, not with |Â12 − 0.5|, so that exact fractions such as 0.44 = 44/100 land on
     * the boundary they are written as rather than one rounding error beside it. NaN (Â12 of an
     * empty sample) has no magnitude: {@link EffectSize#UNDEFINED}.
     */
    public static EffectSize magnitude(double a12) {
        if (Double.isNaN(a12)) {
            return EffectSize.UNDEFINED;
        }
        if (a12 < 0 || a12 > 1) {
            throw new IllegalArgumentException("A12 must be in [0, 1]: " + a12);
        }
        if (a12 >= 0.71 || a12 <= 0.29) {
            return EffectSize.LARGE;
        }
        if (a12 >= 0.64 || a12 <= 0.36) {
            return EffectSize.MEDIUM;
        }
        if (a12 >= 0.56 || a12 <= 0.44) {
            return EffectSize.SMALL;
        }
        return EffectSize.NEGLIGIBLE;
    }
}
