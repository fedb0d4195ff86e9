package sitcov.stats;

import java.util.Arrays;
import java.util.Comparator;
import java.util.stream.IntStream;

/**
 * Ranks with ties given the average of the ranks they span (the "mid-rank" convention of the
 * Mann-Whitney and Wilcoxon tests, e.g. Hollander &amp; Wolfe, Nonparametric Statistical Methods,
 * 2nd ed. 1999, ch. 3 and 4), and the tie term Σ(t³ − t) over tie groups of size t that corrects the
 * variance of both rank statistics under their normal approximations.
 */
public final class Ranks {
    private Ranks() {
    }

    /** Ranks 1..n of {@code values} in input order, tied values sharing their average rank. */
    public static double[] average(double[] values) {
        int[] order = sortedOrder(values);
        double[] ranks = new double[values.length];
        int i = 0;
        while (i < order.length) {
            int j = endOfTies(values, order, i);
            double rank = (i + 1 + j) / 2.0; // average of positions i+1..j
            for (int k = i; k < j; k++) {
                ranks[order[k]] = rank;
            }
            i = j;
        }
        return ranks;
    }

    /** Σ(t³ − t) over the groups of t equal values; zero when all values differ. */
    public static double tieTerm(double[] values) {
        int[] order = sortedOrder(values);
        double sum = 0;
        int i = 0;
        while (i < order.length) {
            int j = endOfTies(values, order, i);
            double t = j - i;
            sum += t * t * t - t;
            i = j;
        }
        return sum;
    }

    /** Whether any two values are equal. */
    public static boolean hasTies(double[] values) {
        return tieTerm(values) > 0;
    }

    private static int[] sortedOrder(double[] values) {
        requireNoNaN(values);
        return IntStream.range(0, values.length).boxed()
            .sorted(Comparator.comparingDouble(k -> values[k]))
            .mapToInt(Integer::intValue).toArray();
    }

    /** The end (exclusive) of the run of values equal to the one at sorted position {@code i}. */
    private static int endOfTies(double[] values, int[] order, int i) {
        int j = i + 1;
        // == rather than Double.compare, so that -0.0 and 0.0 tie as the numbers they are
        while (j < order.length && values[order[j]] == values[order[i]]) {
            j++;
        }
        return j;
    }

    /** A copy of {@code values} sorted ascending, rejecting NaN. */
    static double[] sorted(double[] values) {
        requireNoNaN(values);
        double[] copy = values.clone();
        Arrays.sort(copy);
        return copy;
    }

    private static void requireNoNaN(double[] values) {
        for (double v : values) {
            if (Double.isNaN(v)) {
                throw new IllegalArgumentException("NaN has no rank or order");
            }
        }
    }
}
