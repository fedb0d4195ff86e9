package sitcov.stats;

/**
 * How much more the counts of several binomial samples vary than one shared proportion allows: the
 * Pearson dispersion statistic φ = X²/(k − 1), X² = Σ (yᵢ − nᵢp̂)²/(nᵢp̂(1 − p̂)) with p̂ = Σyᵢ/Σnᵢ over
 * the k samples (McCullagh &amp; Nelder, Generalized Linear Models, 2nd ed. 1989, §4.5). About 1 when
 * every sample draws from the same proportion; well above 1 when the successes cluster in some
 * samples — as a search driver's finds cluster in the replications whose elites hold the situation
 * a fault needs. Pooling such samples as one binomial (a single Fisher test over all maps) then
 * overstates the evidence roughly by the factor φ.
 */
public final class Dispersion {
    private Dispersion() {
    }

    /**
     * φ of the samples with {@code successes[i]} of {@code trials[i]}; NaN with fewer than two
     * samples that have trials, or when the pooled proportion is 0 or 1 (nothing can vary).
     */
    public static double pearson(long[] successes, long[] trials) {
        if (successes.length != trials.length) {
            throw new IllegalArgumentException("successes and trials differ in length: " + successes.length + " vs "
                    + trials.length);
        }
        long y = 0;
        long n = 0;
        int samples = 0;
        for (int i = 0; i < trials.length; i++) {
            if (successes[i] < 0 || successes[i] > trials[i]) {
                throw new IllegalArgumentException("sample " + i + " has " + successes[i] + " successes of " + trials[i]);
            }
            y += successes[i];
            n += trials[i];
            samples += trials[i] > 0 ? 1 : 0;
        }
        if (samples < 2 || y == 0 || y == n) {
            return Double.NaN;
        }
        double p = (double) y / n;
        double chi2 = 0;
        for (int i = 0; i < trials.length; i++) {
            if (trials[i] > 0) {
                double expected = trials[i] * p;
                chi2 += (successes[i] - expected) * (successes[i] - expected) / (expected * (1 - p));
            }
        }
        return chi2 / (samples - 1);
    }
}
