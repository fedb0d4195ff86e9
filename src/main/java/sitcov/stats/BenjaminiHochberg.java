package sitcov.stats;

import java.util.Comparator;
import java.util.stream.IntStream;

/**
 * Benjamini and Hochberg's step-up procedure (1995, "Controlling the false discovery rate", Journal of
 * the Royal Statistical Society B 57:289): among the tests it rejects at level q, the expected share
 * of false rejections is at most q, for independent or positively dependent tests. It suits a
 * screening family — many tests read for which deserve a closer look — where Holm's family-wise
 * control would leave nearly everything unread.
 *
 * <p>With the m p-values sorted ascending, p₍ᵢ₎ becomes min over j ≥ i of min(1, m·p₍ⱼ₎ / j); rejecting
 * where the adjusted p is at most q is the procedure at level q. This is R's {@code p.adjust(p, "BH")}.
 */
public final class BenjaminiHochberg {
    private BenjaminiHochberg() {
    }

    /** BH-adjusted p-values (q-values), in the order of {@code p}. */
    public static double[] adjust(double... p) {
        for (double v : p) {
            if (!(v >= 0 && v <= 1)) {
                throw new IllegalArgumentException("p-values must be in [0, 1]: " + v);
            }
        }
        int m = p.length;
        int[] order = IntStream.range(0, m).boxed().sorted(Comparator.comparingDouble(k -> p[k]))
                .mapToInt(Integer::intValue).toArray();
        double[] adjusted = new double[m];
        double runningMin = 1;
        for (int j = m - 1; j >= 0; j--) {
            runningMin = Math.min(runningMin, (double) m * p[order[j]] / (j + 1));
            adjusted[order[j]] = runningMin;
        }
        return adjusted;
    }

    /** How many of {@code p} the procedure rejects at level {@code q}. */
    public static int discoveries(double q, double... p) {
        return (int) java.util.Arrays.stream(adjust(p)).filter(v -> v <= q).count();
    }
}
