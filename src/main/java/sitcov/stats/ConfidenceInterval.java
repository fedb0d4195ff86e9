package sitcov.stats;

/**
 * A point estimate with the interval around it.
 *
 * @param estimate the point estimate (NaN when there is nothing to estimate from)
 * @param low lower end of the interval
 * @param high upper end of the interval
 */
public record ConfidenceInterval(double estimate, double low, double high) {
    public ConfidenceInterval {
        if (low > high) {
            throw new IllegalArgumentException("interval ends reversed: " + low + " > " + high);
        }
    }

    /** Whether {@code value} lies in the closed interval. */
    public boolean contains(double value) {
        return low <= value && value <= high;
    }

    /** high − low. */
    public double width() {
        return high - low;
    }
}
