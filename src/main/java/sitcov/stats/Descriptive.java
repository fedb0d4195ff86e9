package sitcov.stats;

/**
 * Means, medians and quartiles for summary tables. Quantiles follow definition 7 of Hyndman &amp;
 * Fan (1996, "Sample quantiles in statistical packages", The American Statistician 50:361), the
 * default of R's {@code quantile} and of NumPy, so the figures can be reproduced there: the
 * p-quantile of the sorted x₁..xₙ interpolates linearly at position h = (n − 1)p + 1.
 */
public final class Descriptive {
    private Descriptive() {
    }

    /** The lower quartile, median and upper quartile, all by definition 7. */
    public record Quartiles(double lower, double median, double upper) {
        /** The interquartile range. */
        public double iqr() {
            return upper - lower;
        }
    }

    /** The arithmetic mean; NaN for no values. */
    public static double mean(double[] values) {
        if (values.length == 0) {
            return Double.NaN;
        }
        double sum = 0;
        for (double v : values) {
            sum += v;
        }
        return sum / values.length;
    }

    /** The sample variance with divisor n − 1; NaN for fewer than two values. */
    public static double variance(double[] values) {
        if (values.length < 2) {
            return Double.NaN;
        }
        double mean = mean(values);
        double sum = 0;
        for (double v : values) {
            sum += (v - mean) * (v - mean);
        }
        return sum / (values.length - 1);
    }

    /** The {@code p}-quantile by Hyndman &amp; Fan's definition 7; NaN for no values. */
    public static double quantile(double[] values, double p) {
        return quantileOfSorted(Ranks.sorted(values), p);
    }

    /** The median (definition 7 gives the usual middle value or mean of the two middle values). */
    public static double median(double[] values) {
        return quantile(values, 0.5);
    }

    /** The quartiles by definition 7. */
    public static Quartiles quartiles(double[] values) {
        double[] sorted = Ranks.sorted(values);
        return new Quartiles(quantileOfSorted(sorted, 0.25), quantileOfSorted(sorted, 0.5),
            quantileOfSorted(sorted, 0.75));
    }

    /** Definition 7 on values already sorted ascending (the bootstrap sorts once, reads two). */
    static double quantileOfSorted(double[] sorted, double p) {
        if (Double.isNaN(p) || p < 0 || p > 1) {
            throw new IllegalArgumentException("probability must be in [0, 1]: " + p);
        }
        if (sorted.length == 0) {
            return Double.NaN;
        }
        double h = (sorted.length - 1) * p; // zero-based position
        int lo = (int) Math.floor(h);
        int hi = Math.min(lo + 1, sorted.length - 1);
        if (sorted[hi] == sorted[lo]) {
            return sorted[lo]; // between two equal values, infinite ones too (an unbounded rate ratio)
        }
        return sorted[lo] + (h - lo) * (sorted[hi] - sorted[lo]);
    }
}
