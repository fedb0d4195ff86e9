package sitcov.stats;

/**
 * The two-sided Wilcoxon signed-rank test of paired samples: do the paired differences x − y lean
 * to one side of zero? It compares, say, two configurations run on the same maps.
 *
 * <p>Zero differences are dropped before ranking, Wilcoxon's own convention (Wilcoxon 1945,
 * Biometrics Bulletin 1:80; the default of R's {@code wilcox.test}), so n counts the non-zero pairs.
 * The absolute differences get mid-ranks, and W⁺ is the sum of the ranks of the positive ones. The
 * p-value is
 * <ul>
 * <li>exact when 1 ≤ n ≤ {@value #EXACT_MAX} and no absolute differences tie: each of the 2ⁿ sign
 * patterns is equally likely, the distribution of W⁺ is counted from the generating function
 * Π_{i=1..n}(1 + q^i), and p = min(1, 2·min(P(W⁺ ≤ w), P(W⁺ ≥ w)));</li>
 * <li>otherwise from the normal approximation with tie-corrected variance
 * σ² = n(n + 1)(2n + 1)/24 − Σ(t³ − t)/48 and a continuity correction of ½ towards the mean,
 * z = (W⁺ − n(n + 1)/4 ∓ ½)/σ, p = 2·Φ(−|z|) (Hollander &amp; Wolfe, Nonparametric Statistical
 * Methods, 2nd ed. 1999, ch. 3), as R's {@code wilcox.test(x, y, paired = TRUE, exact = FALSE)}
 * computes it.</li>
 * </ul>
 * One difference from R: R falls back to the normal approximation whenever zeros were dropped,
 * while here the exact distribution of the remaining n differences is used, which is valid because
 * the dropped zeros carry no sign.
 *
 * <p>A one-sided test ({@link Alternative#GREATER}: x tends to exceed y) takes the one tail, P(W⁺ ≥ w)
 * exactly or Φ(−z) with the correction of ½ towards the mean, as R's {@code alternative = "greater"}.
 * {@link #smallestP} is the least p-value the test can give on differences of the observed sizes,
 * reached when all of them lean the same way: with n untied non-zero differences 2/2ⁿ two-sided and
 * 1/2ⁿ one-sided, so five paired replications can never reach p &lt; 0.05 two-sided (2/32 = 0.0625).
 * A test whose smallest p is above the level cannot find anything, which a verdict must say.
 */
public final class WilcoxonSignedRank {
    /**
     * Largest number of non-zero differences for which the exact distribution is used: R's rule (exact
     * below 50), so an experiment of 30 paired replications gets exact p-values where nothing ties.
     */
    public static final int EXACT_MAX = 49;

    private WilcoxonSignedRank() {
    }

    /**
     * The outcome of a test.
     *
     * @param wPlus W⁺, the sum of the ranks of the positive differences
     * @param n the number of non-zero differences that were ranked
     * @param z the continuity-corrected normal deviate, or NaN when the p-value is exact
     * @param p the two-sided p-value; 1 when every difference is zero
     * @param exact whether p comes from the exact distribution (true, trivially, when n = 0)
     */
    public record Result(double wPlus, int n, double z, double p, boolean exact) {
    }

    /** Which way the test looks. */
    public enum Alternative {
        /** x and y differ either way. */
        TWO_SIDED,
        /** x tends to exceed y (the differences x − y lean positive). */
        GREATER,
        /** x tends to fall below y. */
        LESS
    }

    /** Tests the pairs (x[i], y[i]) two-sided; the arrays must have the same length and no NaN. */
    public static Result test(double[] x, double[] y) {
        return test(x, y, Alternative.TWO_SIDED);
    }

    /** Tests the pairs (x[i], y[i]) against {@code alternative}. */
    public static Result test(double[] x, double[] y, Alternative alternative) {
        if (x.length != y.length) {
            throw new IllegalArgumentException("paired samples differ in length: " + x.length + " vs " + y.length);
        }
        double[] d = new double[x.length];
        for (int i = 0; i < d.length; i++) {
            d[i] = x[i] - y[i];
        }
        return test(d, alternative);
    }

    /** Tests whether the differences {@code d} are centred on zero, two-sided. */
    public static Result test(double[] d) {
        return test(d, Alternative.TWO_SIDED);
    }

    /**
     * The least p-value {@link #test(double[], Alternative)} can give for differences of the sizes of
     * {@code d}: all of them on the side the alternative looks for. 1 when no difference is non-zero.
     */
    public static double smallestP(double[] d, Alternative alternative) {
        double[] leaning = new double[d.length];
        for (int i = 0; i < d.length; i++) {
            leaning[i] = alternative == Alternative.LESS ? -Math.abs(d[i]) : Math.abs(d[i]);
        }
        return test(leaning, alternative).p();
    }

    /** Tests whether the differences {@code d} are centred on zero, against {@code alternative}. */
    public static Result test(double[] d, Alternative alternative) {
        int n = 0;
        for (double v : d) {
            if (Double.isNaN(v)) {
                throw new IllegalArgumentException("NaN difference");
            }
            n += v != 0 ? 1 : 0;
        }
        if (n == 0) {
            return new Result(0, 0, Double.NaN, 1, true); // nothing to rank: no evidence either way
        }
        double[] magnitudes = new double[n];
        boolean[] positive = new boolean[n];
        int k = 0;
        for (double v : d) {
            if (v != 0) {
                magnitudes[k] = Math.abs(v);
                positive[k++] = v > 0;
            }
        }
        double[] ranks = Ranks.average(magnitudes);
        double wPlus = 0;
        for (int i = 0; i < n; i++) {
            wPlus += positive[i] ? ranks[i] : 0;
        }
        double ties = Ranks.tieTerm(magnitudes);
        if (ties == 0 && n <= EXACT_MAX) {
            return new Result(wPlus, n, Double.NaN, exactP(Math.round(wPlus), n, alternative), true);
        }
        double variance = n * (n + 1.0) * (2 * n + 1) / 24 - ties / 48;
        if (variance <= 0) {
            return new Result(wPlus, n, 0, 1, false);
        }
        double shift = wPlus - n * (n + 1.0) / 4;
        double correction = switch (alternative) {
            case TWO_SIDED -> Math.signum(shift) * 0.5;
            case GREATER -> 0.5;
            case LESS -> -0.5;
        };
        double z = (shift - correction) / Math.sqrt(variance);
        double p = switch (alternative) {
            case TWO_SIDED -> Math.min(1, 2 * Normal.cdf(-Math.abs(z)));
            case GREATER -> Normal.cdf(-z);
            case LESS -> Normal.cdf(z);
        };
        return new Result(wPlus, n, z, p, false);
    }

    /** Exact p of W⁺ = w among n untied non-zero differences. */
    static double exactP(long w, int n, Alternative alternative) {
        int max = n * (n + 1) / 2;
        long[] c = new long[max + 1]; // c[s]: sign patterns with W+ = s; at most 2^49, exact in a long and a double
        c[0] = 1;
        for (int i = 1; i <= n; i++) {
            for (int s = max; s >= i; s--) {
                c[s] += c[s - i];
            }
        }
        double all = Math.pow(2, n);
        double atMost = 0;
        double atLeast = 0;
        for (int s = 0; s <= max; s++) {
            atMost += s <= w ? c[s] : 0;
            atLeast += s >= w ? c[s] : 0;
        }
        return switch (alternative) {
            case TWO_SIDED -> Math.min(1, 2 * Math.min(atMost, atLeast) / all);
            case GREATER -> atLeast / all;
            case LESS -> atMost / all;
        };
    }
}
