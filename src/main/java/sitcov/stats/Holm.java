package sitcov.stats;

import java.util.Comparator;
import java.util.stream.IntStream;

/**
 * Holm's step-down correction for multiple comparisons (Holm 1979, "A simple sequentially rejective
 * multiple test procedure", Scandinavian Journal of Statistics 6:65): it controls the family-wise
 * error rate like Bonferroni does, yet rejects at least as often. When a report tests, say, every
 * pair of generators, it adjusts those p-values together.
 *
 * <p>With the m p-values sorted ascending, p₍ᵢ₎ becomes max over j ≤ i of min(1, (m − j + 1)·p₍ⱼ₎);
 * the running maximum keeps the adjusted values in the order of the raw ones. Rejecting where the
 * adjusted p is at most α is Holm's procedure at level α. This is R's {@code p.adjust(p, "holm")}.
 */
public final class Holm {
    private Holm() {
    }

    /** Holm-adjusted p-values, in the order of {@code p}. */
    public static double[] adjust(double... p) {
        for (double v : p) {
            if (!(v >= 0 && v <= 1)) {
                throw new IllegalArgumentException("p-values must be in [0, 1]: " + v);
            }
        }
        int m = p.length;
        int[] order = IntStream.range(0, m).boxed()
            .sorted(Comparator.comparingDouble(k -> p[k]))
            .mapToInt(Integer::intValue).toArray();
        double[] adjusted = new double[m];
        double runningMax = 0;
        for (int j = 0; j < m; j++) {
            runningMax = Math.max(runningMax, Math.min(1, (m - j) * p[order[j]]));
            adjusted[order[j]] = runningMax;
        }
        return adjusted;
    }
}
