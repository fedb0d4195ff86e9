package sitcov.stats;

import java.util.Arrays;
import java.util.random.RandomGenerator;

/**
 * Percentile bootstrap intervals for a difference of means (Efron &amp; Tibshirani, An Introduction
 * to the Bootstrap, 1993, ch. 13): the difference is recomputed on B resamples drawn with
 * replacement, and the interval runs between the α/2 and 1 − α/2 quantiles of those B values
 * (quantile definition 7, see {@link Descriptive}). It needs no normality, which matters for the
 * skewed metrics of simulation runs, and says how large a difference is where a rank test only says
 * whether there is one.
 *
 * <p>All randomness comes from the {@link RandomGenerator} the caller passes in, in a fixed order
 * (per resample: the indices into x, then those into y), so a generator in the same state gives the
 * same interval; this class never seeds a generator of its own.
 */
public final class Bootstrap {
    /** The default number of resamples: enough for the 2.5 % and 97.5 % percentiles to settle. */
    public static final int DEFAULT_RESAMPLES = 2000;

    /** The interval of an empty sample: nothing to estimate from, so NaN throughout. */
    public static final ConfidenceInterval NOTHING = new ConfidenceInterval(Double.NaN, Double.NaN, Double.NaN);

    private Bootstrap() {
    }

    /** mean(x) − mean(y) for independent samples, with a 95 % interval from 2000 resamples. */
    public static ConfidenceInterval meanDifference(double[] x, double[] y, RandomGenerator random) {
        return meanDifference(x, y, DEFAULT_RESAMPLES, 0.95, random);
    }

    /**
     * mean(x) − mean(y) for independent samples: each resample draws x.length values from x and
     * y.length values from y, each with replacement. An empty sample gives {@link #NOTHING}, drawing nothing.
     */
    public static ConfidenceInterval meanDifference(double[] x, double[] y, int resamples, double confidence,
            RandomGenerator random) {
        check(x, resamples, confidence);
        check(y, resamples, confidence);
        if (x.length == 0 || y.length == 0) {
            return NOTHING;
        }
        double[] replicates = new double[resamples];
        for (int b = 0; b < resamples; b++) {
            replicates[b] = resampledMean(x, random) - resampledMean(y, random);
        }
        return percentile(Descriptive.mean(x) - Descriptive.mean(y), replicates, confidence);
    }

    /** The mean of the paired differences x[i] − y[i], with a 95 % interval from 2000 resamples. */
    public static ConfidenceInterval pairedMeanDifference(double[] x, double[] y, RandomGenerator random) {
        return pairedMeanDifference(x, y, DEFAULT_RESAMPLES, 0.95, random);
    }

    /** The mean of the paired differences x[i] − y[i]: each resample draws whole pairs; no pairs give {@link #NOTHING}. */
    public static ConfidenceInterval pairedMeanDifference(double[] x, double[] y, int resamples, double confidence,
            RandomGenerator random) {
        if (x.length != y.length) {
            throw new IllegalArgumentException("paired samples differ in length: " + x.length + " vs " + y.length);
        }
        double[] d = new double[x.length];
        for (int i = 0; i < d.length; i++) {
            d[i] = x[i] - y[i];
        }
        check(d, resamples, confidence);
        if (d.length == 0) {
            return NOTHING;
        }
        double[] replicates = new double[resamples];
        for (int b = 0; b < resamples; b++) {
            replicates[b] = resampledMean(d, random);
        }
        return percentile(Descriptive.mean(d), replicates, confidence);
    }

    /**
     * The ratio of two rates over paired units (replications): (Σ eventsA / Σ exposureA) over
     * (Σ eventsB / Σ exposureB), with a 95 % interval from 2000 resamples of whole units, so events
     * that cluster in a few units widen it as they should. A resample whose ratio is undefined (no
     * events on either side, or no exposure) is left out; with no units, or an undefined ratio, {@link #NOTHING}.
     */
    public static ConfidenceInterval pairedRateRatio(double[] eventsA, double[] exposureA, double[] eventsB,
                                                     double[] exposureB, RandomGenerator random) {
        int n = eventsA.length;
        if (exposureA.length != n || eventsB.length != n || exposureB.length != n) {
            throw new IllegalArgumentException("paired rates need as many units on each side");
        }
        double estimate = rateRatio(eventsA, exposureA, eventsB, exposureB, null);
        if (n == 0 || Double.isNaN(estimate)) {
            return NOTHING;
        }
        double[] replicates = new double[DEFAULT_RESAMPLES];
        int kept = 0;
        int[] units = new int[n];
        for (int b = 0; b < DEFAULT_RESAMPLES; b++) {
            for (int i = 0; i < n; i++) {
                units[i] = random.nextInt(n);
            }
            double r = rateRatio(eventsA, exposureA, eventsB, exposureB, units);
            if (!Double.isNaN(r)) {
                replicates[kept++] = r;
            }
        }
        return kept == 0 ? new ConfidenceInterval(estimate, Double.NaN, Double.NaN)
                : percentile(estimate, Arrays.copyOf(replicates, kept), 0.95);
    }

    /** The rate ratio over {@code units} (all of them when null): NaN when undefined, +∞ when only B has none. */
    private static double rateRatio(double[] eventsA, double[] exposureA, double[] eventsB, double[] exposureB,
                                    int[] units) {
        double ea = 0;
        double xa = 0;
        double eb = 0;
        double xb = 0;
        int n = units == null ? eventsA.length : units.length;
        for (int k = 0; k < n; k++) {
            int i = units == null ? k : units[k];
            ea += eventsA[i];
            xa += exposureA[i];
            eb += eventsB[i];
            xb += exposureB[i];
        }
        if (xa <= 0 || xb <= 0 || ea == 0 && eb == 0) {
            return Double.NaN;
        }
        return (ea / xa) / (eb / xb);
    }

    private static double resampledMean(double[] values, RandomGenerator random) {
        double sum = 0;
        for (int i = 0; i < values.length; i++) {
            sum += values[random.nextInt(values.length)];
        }
        return sum / values.length;
    }

    private static ConfidenceInterval percentile(double estimate, double[] replicates, double confidence) {
        Arrays.sort(replicates);
        double alpha = 1 - confidence;
        return new ConfidenceInterval(estimate, Descriptive.quantileOfSorted(replicates, alpha / 2),
            Descriptive.quantileOfSorted(replicates, 1 - alpha / 2));
    }

    private static void check(double[] values, int resamples, double confidence) {
        for (double v : values) {
            if (!Double.isFinite(v)) {
                throw new IllegalArgumentException("values must be finite: " + v);
            }
        }
        if (resamples < 1) {
            throw new IllegalArgumentException("need at least one resample: " + resamples);
        }
        if (!(confidence > 0 && confidence < 1)) {
            throw new IllegalArgumentException("confidence must be in (0, 1): " + confidence);
        }
    }
}
