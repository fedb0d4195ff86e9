package sitcov.stats;

/**
 * The smallest difference a paired comparison of n replications could have detected: the mean
 * difference δ at which a paired t-test at level α has the given power, from the observed spread s of
 * the differences, δ = (t_{1−α/k, n−1} + t_{power, n−1})·s/√n with k = 2 for a two-sided test and 1 for
 * a one-sided one (the usual normal-theory approximation with the t quantiles; Chow, Shao &amp; Wang,
 * Sample Size Calculations in Clinical Research, 2nd ed. 2008, §3.2). The signed-rank test sitcov
 * decides with has an asymptotic efficiency of at least 0.864 against the t-test (0.955 on normal
 * data; Hodges &amp; Lehmann 1956), so its own detectable difference is at most about 8 % larger: "no
 * difference shown" then means no difference of this size or more was likely missed.
 */
public final class DetectableDifference {
    private DetectableDifference() {
    }

    /**
     * δ for a test of n paired differences with standard deviation {@code sd}.
     *
     * @param twoSided whether the test is two-sided (α split over both tails)
     */
    public static double pairedT(double sd, int n, double alpha, boolean twoSided, double power) {
        if (n < 2 || !(sd >= 0) || !(alpha > 0 && alpha < 1) || !(power > 0 && power < 1)) {
            throw new IllegalArgumentException("need n >= 2, sd >= 0, 0 < alpha < 1 and 0 < power < 1: n=" + n + ", sd="
                    + sd + ", alpha=" + alpha + ", power=" + power);
        }
        double df = n - 1;
        double critical = StudentT.quantile(1 - (twoSided ? alpha / 2 : alpha), df);
        return (critical + StudentT.quantile(power, df)) * sd / Math.sqrt(n);
    }
}
