package sitcov.stats;

/**
 * The Wilson score interval for a binomial proportion (Wilson 1927, "Probable inference, the law of
 * succession, and statistical inference", JASA 22:209), method 3 of Newcombe's comparison (Newcombe
 * 1998, "Two-sided confidence intervals for the single proportion: comparison of seven methods",
 * Statistics in Medicine 17:857). Unlike the textbook Wald interval p̂ ± z√(p̂(1 − p̂)/n), it keeps
 * close to its nominal coverage for small n and for proportions near 0 or 1 — such as the fraction
 * of runs in which a rare fault shows — and never leaves [0, 1]:
 * <pre>
 *   (2k + z² ± z·√(z² + 4k(n − k)/n)) / (2(n + z²))
 * </pre>
 */
public final class Wilson {
    private Wilson() {
    }

    /** The 95 % interval for {@code k} successes in {@code n} trials. */
    public static ConfidenceInterval interval(long k, long n) {
        return interval(k, n, 0.95);
    }

    /** The interval of the given two-sided {@code confidence} in (0, 1). */
    public static ConfidenceInterval interval(long k, long n, double confidence) {
        if (!(confidence > 0 && confidence < 1)) {
            throw new IllegalArgumentException("confidence must be in (0, 1): " + confidence);
        }
        return intervalForZ(k, n, Normal.quantile(0.5 + confidence / 2));
    }

    /**
     * The interval for a given normal deviate {@code z} (1.959964 for 95 %). With no trials the
     * proportion is unknown: the estimate is NaN and the interval all of [0, 1].
     */
    public static ConfidenceInterval intervalForZ(long k, long n, double z) {
        if (n < 0 || k < 0 || k > n) {
            throw new IllegalArgumentException("need 0 <= k <= n: k = " + k + ", n = " + n);
        }
        if (!(z > 0)) {
            throw new IllegalArgumentException("z must be positive: " + z);
        }
        if (n == 0) {
            return new ConfidenceInterval(Double.NaN, 0, 1);
        }
        double z2 = z * z;
        double centre = 2 * k + z2;
        double spread = z * Math.sqrt(z2 + 4.0 * k * (n - k) / n);
        double denominator = 2 * (n + z2);
        // At k = 0 or k = n the formula gives the end exactly in real arithmetic; pin it there.
        double low = k == 0 ? 0 : (centre - spread) / denominator;
        double high = k == n ? 1 : (centre + spread) / denominator;
        return new ConfidenceInterval(k / (double) n, low, high);
    }
}
