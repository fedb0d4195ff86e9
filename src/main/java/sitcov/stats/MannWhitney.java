package sitcov.stats;

/**
 * The two-sided Mann-Whitney U test (Wilcoxon rank-sum test) of two independent samples: does one
 * tend to give larger values than the other? It compares, say, a metric of two generators over
 * replicated runs without assuming any distribution.
 *
 * <p>U of the first sample counts the pairs (xᵢ, yⱼ) with xᵢ &gt; yⱼ, ties counting one half, and is
 * computed from mid-ranks as U = R₁ − m(m + 1)/2 (Mann &amp; Whitney 1947, Annals of Mathematical
 * Statistics 18:50). The p-value is
 * <ul>
 * <li>exact when both samples have at most {@value #EXACT_MAX} values and there are no ties: the
 * permutation distribution of U, counted with Harding's generating-function recursion (Harding
 * 1984, Applied Statistics 33:1), and p = min(1, 2·min(P(U ≤ u), P(U ≥ u)));</li>
 * <li>otherwise from the normal approximation with the tie-corrected variance
 * σ² = mn/12 · ((N + 1) − Σ(t³ − t)/(N(N − 1))) and a continuity correction of ½ towards the mean,
 * z = (U − mn/2 ∓ ½)/σ, p = 2·Φ(−|z|) (Hollander &amp; Wolfe, Nonparametric Statistical
 * Methods, 2nd ed. 1999, ch. 4).</li>
 * </ul>
 * The normal branch is R's {@code wilcox.test(x, y, exact = FALSE, correct = TRUE)}; the exact
 * branch is R's default for such small untied samples (R stays exact up to 49 values a sample).
 */
public final class MannWhitney {
    /** Largest size of either sample for which the exact distribution is used. */
    public static final int EXACT_MAX = 20;

    private MannWhitney() {
    }

    /**
     * The outcome of a test.
     *
     * @param u U of the first sample: pairs where it is larger, plus half the tied pairs
     * @param z the continuity-corrected normal deviate, or NaN when the p-value is exact
     * @param p the two-sided p-value; NaN when a sample is empty (nothing to rank, nothing claimed)
     * @param exact whether p comes from the exact permutation distribution
     */
    public record Result(double u, double z, double p, boolean exact) {
    }

    /** Tests {@code x} against {@code y}, both free of NaN; an empty sample gives NaN throughout. */
    public static Result test(double[] x, double[] y) {
        if (x.length == 0 || y.length == 0) {
            return new Result(Double.NaN, Double.NaN, Double.NaN, false);
        }
        int m = x.length;
        int n = y.length;
        double[] pooled = new double[m + n];
        System.arraycopy(x, 0, pooled, 0, m);
        System.arraycopy(y, 0, pooled, m, n);
        double[] ranks = Ranks.average(pooled);
        double rankSum = 0;
        for (int i = 0; i < m; i++) {
            rankSum += ranks[i];
        }
        double u = rankSum - m * (m + 1.0) / 2;
        double ties = Ranks.tieTerm(pooled);
        if (ties == 0 && m <= EXACT_MAX && n <= EXACT_MAX) {
            return new Result(u, Double.NaN, exactP(Math.round(u), m, n), true);
        }
        int total = m + n;
        double variance = m * (double) n / 12 * ((total + 1) - ties / (total * (total - 1.0)));
        if (variance <= 0) {
            return new Result(u, 0, 1, false); // every value tied: no evidence either way
        }
        double shift = u - m * (double) n / 2;
        double z = (shift - Math.signum(shift) * 0.5) / Math.sqrt(variance);
        return new Result(u, z, Math.min(1, 2 * Normal.cdf(-Math.abs(z))), false);
    }

    /** Two-sided exact p of U = u for samples of m and n without ties. */
    static double exactP(long u, int m, int n) {
        long[] counts = uCounts(m, n);
        double all = 0;
        double atMost = 0;
        double atLeast = 0;
        for (int k = 0; k < counts.length; k++) {
            all += counts[k];
            atMost += k <= u ? counts[k] : 0;
            atLeast += k >= u ? counts[k] : 0;
        }
        return Math.min(1, 2 * Math.min(atMost, atLeast) / all);
    }

    /**
     * How many of the C(m + n, m) equally likely arrangements give U = 0..mn: the coefficients of
     * the Gaussian binomial Π_{i=1..m} (1 − q^{n+i})/(1 − q^i) (Harding 1984). Each factor is a
     * multiplication by (1 − q^{n+i}) and a division by (1 − q^i), both done in place; counts stay
     * below C(40, 20) ≈ 1.4e11, so longs are exact.
     */
    static long[] uCounts(int m, int n) {
        int max = m * n;
        long[] c = new long[max + 1];
        c[0] = 1;
        for (int i = 1; i <= m; i++) {
            for (int k = max; k >= n + i; k--) {
                c[k] -= c[k - n - i];
            }
            for (int k = i; k <= max; k++) {
                c[k] += c[k - i];
            }
        }
        return c;
    }
}
