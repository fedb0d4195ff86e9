package sitcov.estimate;

import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import sitcov.stats.ConfidenceInterval;
import sitcov.stats.Wilson;

/** The two estimators of a failure rate, with their 95 % intervals. */
public final class Estimators {
    static final double Z95 = 1.959963984540054;

    private Estimators() {
    }

    /** Plain Monte Carlo: the share of runs that failed, with Wilson's interval. */
    public static Estimate monteCarlo(List<Sample> samples, Failing requirement) {
        int failing = (int) samples.stream().filter(s -> s.failed(requirement)).count();
        int n = samples.size();
        ConfidenceInterval ci = n == 0 ? new ConfidenceInterval(0, 0, 1) : Wilson.intervalForZ(failing, n, Z95);
        double rate = n == 0 ? 0 : (double) failing / n;
        return new Estimate("mc", requirement, n, ticks(samples), failing, rate, ci.low(), ci.high(),
                (ci.high() - ci.low()) / 2, n);
    }

    /**
     * Importance sampling: the mean of w·1{failed} over the runs, w = p_nominal / p_proposal. Each
     * stage of each replication drew its runs from a proposal of its own, fixed before the stage
     * began, so each stage's mean is an unbiased estimate and the variance is summed over them
     * (strata), each from its runs' sample variance; the interval is normal, cut at 0.
     */
    public static Estimate importanceSampling(List<Sample> samples, Failing requirement) {
        Map<String, double[]> strata = new TreeMap<>(); // replication and stage -> {n, Σx, Σx²}
        double sumW = 0;
        double sumW2 = 0;
        int failing = 0;
        for (Sample s : samples) {
            double w = s.weight();
            double x = s.failed(requirement) ? w : 0;
            failing += x > 0 ? 1 : 0;
            double[] m = strata.computeIfAbsent(s.replication() + ":" + s.stage(), r -> new double[3]);
            m[0]++;
            m[1] += x;
            m[2] += x * x;
            sumW += w;
            sumW2 += w * w;
        }
        int n = samples.size();
        double total = 0;
        double variance = 0;
        for (double[] m : strata.values()) {
            total += m[1];
            double mean = m[1] / m[0];
            double s2 = m[0] > 1 ? Math.max(0, (m[2] - m[0] * mean * mean) / (m[0] - 1)) : 0;
            // a stratum's share of the mean is (n_r / n) x its mean, whose variance is s2 / n_r
            variance += (m[0] / n) * (m[0] / n) * s2 / m[0];
        }
        double rate = n == 0 ? 0 : total / n;
        double half = Z95 * Math.sqrt(variance);
        double ess = sumW2 == 0 ? 0 : sumW * sumW / sumW2;
        return new Estimate("is", requirement, n, ticks(samples), failing, rate, Math.max(0, rate - half), rate + half,
                half, ess);
    }

    private static long ticks(List<Sample> samples) {
        return samples.stream().mapToLong(Sample::ticks).sum();
    }
}
