package sitcov.stats;

/**
 * Schuirmann's two one-sided tests (TOST) of equivalence for paired samples (Schuirmann 1987, "A
 * comparison of the two one-sided tests procedure and the power approach for assessing the
 * equivalence of average bioavailability", Journal of Pharmacokinetics and Biopharmaceutics 15:657):
 * is the mean of the paired differences inside (−margin, +margin)? Each bound is tested on its own
 * with a one-sided t-test on the n − 1 degrees of freedom of the differences, t₁ = (d̄ + margin)/se
 * against "d̄ ≤ −margin" and t₂ = (d̄ − margin)/se against "d̄ ≥ +margin"; equivalence is shown at
 * level α when both reject, so the TOST p-value is the larger of the two. That is the same as the
 * (1 − 2α) t interval of the mean difference lying inside the margins, which {@link Result#low} and
 * {@link Result#high} give. This is what R's {@code TOSTER::t_TOST(paired = TRUE)} and
 * {@code equivalence::tost(paired = TRUE)} compute.
 *
 * <p>Differences without spread (every pair differs by the same amount) give no standard error to
 * test with: the p-values are then NaN, and nothing is claimed. (On a handful of pairs identical
 * differences are no evidence of equivalence; the caller says what they are instead.)
 */
public final class Tost {
    private Tost() {
    }

    /**
     * The outcome of the two tests.
     *
     * @param mean the mean paired difference
     * @param p the TOST p-value, max(pLower, pUpper): equivalence is shown at level α when p ≤ α
     * @param pLower the p-value of the test against "mean ≤ −margin"
     * @param pUpper the p-value of the test against "mean ≥ +margin"
     * @param low the lower end of the (1 − 2α) t interval of the mean difference
     * @param high its upper end
     */
    public record Result(double mean, double margin, double p, double pLower, double pUpper, double low, double high) {
        /** Whether equivalence is shown at level {@code alpha} (never without spread). */
        public boolean equivalent(double alpha) {
            return p <= alpha;
        }
    }

    /** The TOST of the differences x[i] − y[i] against ±{@code margin}, its interval at level {@code alpha}. */
    public static Result paired(double[] x, double[] y, double margin, double alpha) {
        if (x.length != y.length) {
            throw new IllegalArgumentException("paired samples differ in length: " + x.length + " vs " + y.length);
        }
        double[] d = new double[x.length];
        for (int i = 0; i < d.length; i++) {
            d[i] = x[i] - y[i];
        }
        return ofDifferences(d, margin, alpha);
    }

    /**
     * The TOST of paired differences {@code d} against ±{@code margin}. Fewer than two pairs give no
     * standard error to test with or to build an interval from: NaN p-values and interval ends.
     */
    public static Result ofDifferences(double[] d, double margin, double alpha) {
        if (d.length < 2) {
            checkLevels(margin, alpha);
            return new Result(Descriptive.mean(d), margin, Double.NaN, Double.NaN, Double.NaN, Double.NaN, Double.NaN);
        }
        return ofSummary(Descriptive.mean(d), Math.sqrt(Descriptive.variance(d)), d.length, margin, alpha);
    }

    /** The TOST from the mean and standard deviation of n paired differences. */
    public static Result ofSummary(double mean, double sd, int n, double margin, double alpha) {
        checkLevels(margin, alpha);
        if (n < 2 || !(sd >= 0)) {
            throw new IllegalArgumentException("TOST needs n >= 2 and sd >= 0: n=" + n + ", sd=" + sd);
        }
        if (sd == 0) {
            return new Result(mean, margin, Double.NaN, Double.NaN, Double.NaN, mean, mean);
        }
        double df = n - 1;
        double se = sd / Math.sqrt(n);
        double pLower = 1 - StudentT.cdf((mean + margin) / se, df);
        double pUpper = StudentT.cdf((mean - margin) / se, df);
        double q = StudentT.quantile(1 - alpha, df);
        return new Result(mean, margin, Math.max(pLower, pUpper), pLower, pUpper, mean - q * se, mean + q * se);
    }

    private static void checkLevels(double margin, double alpha) {
        if (!(margin > 0) || !(alpha > 0 && alpha < 0.5)) {
            throw new IllegalArgumentException("TOST needs margin > 0 and 0 < alpha < 0.5: margin=" + margin + ", alpha="
                    + alpha);
        }
    }
}
