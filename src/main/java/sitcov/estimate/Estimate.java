package sitcov.estimate;

/**
 * A failure rate estimated from some runs.
 *
 * @param method     {@code mc} or {@code is}
 * @param failing    runs that failed the requirement
 * @param halfWidth  half the 95 % interval's width (Wilson's for plain Monte Carlo; 1.96 standard
 *                   errors for importance sampling, before the interval is cut at 0)
 * @param ess        effective sample size, (Σw)² / Σw² (the runs themselves for plain Monte Carlo)
 */
public record Estimate(String method, Failing requirement, int runs, long ticks, int failing, double rate,
                       double low, double high, double halfWidth, double ess) {
    /** The half-width relative to the rate; infinite when no run failed. */
    public double relativeHalfWidth() {
        return rate > 0 ? halfWidth / rate : Double.POSITIVE_INFINITY;
    }

    /** The standard error the half-width stands for. */
    public double standardError() {
        return halfWidth / Estimators.Z95;
    }
}
