package sitcov.figures;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.TreeSet;
import java.util.function.DoubleUnaryOperator;
import sitcov.stats.Descriptive;

/**
 * Replications' curves of one driver read at each of {@code xs}: per point the median and the
 * quartiles over replications. Up to {@code allRan} every replication was still running; beyond,
 * a replication that had stopped counts with the value it stopped at.
 */
record Band(double[] xs, double[] lower, double[] median, double[] upper, double allRan) {
    static Band of(double[] xs, List<? extends DoubleUnaryOperator> runs, double allRan) {
        if (runs.isEmpty()) {
            return new Band(new double[0], new double[0], new double[0], new double[0], 0);
        }
        double[][] q = new double[3][xs.length];
        double[] values = new double[runs.size()];
        for (int i = 0; i < xs.length; i++) {
            for (int r = 0; r < values.length; r++) {
                values[r] = runs.get(r).applyAsDouble(xs[i]);
            }
            Descriptive.Quartiles quartiles = Descriptive.quartiles(values);
            q[0][i] = quartiles.lower();
            q[1][i] = quartiles.median();
            q[2][i] = quartiles.upper();
        }
        return new Band(xs, q[0], q[1], q[2], allRan);
    }

    /**
     * Where step curves with these steps can change, from 0 to {@code end}: 0, every step up to
     * {@code end}, and {@code end}. Their median and quartiles are step curves that change only there,
     * so reading them at these points draws them exactly.
     */
    static double[] breaks(double end, List<double[]> steps) {
        TreeSet<Double> at = new TreeSet<>(List.of(0.0, Math.max(0, end)));
        for (double[] xs : steps) {
            for (double x : xs) {
                if (x > 0 && x < end) {
                    at.add(x);
                }
            }
        }
        return at.stream().mapToDouble(Double::doubleValue).toArray();
    }

    /** A step curve: {@code ys[i]} from {@code xs[i]} (ascending) until the next; 0 before the first. */
    static DoubleUnaryOperator steps(double[] xs, double[] ys) {
        return at -> {
            int lo = 0;
            int hi = xs.length; // the first index past at lies in [lo, hi]
            while (lo < hi) {
                int mid = (lo + hi) >>> 1;
                if (xs[mid] <= at) {
                    lo = mid + 1;
                } else {
                    hi = mid;
                }
            }
            return lo == 0 ? 0 : ys[lo - 1];
        };
    }

    /**
     * What the figure must say of medians that are the same from end to end (their lines lie side by
     * side, and a reader could take that for a small difference), e.g. "the medians of random and
     * coverage-search are the same"; empty when all differ.
     */
    static String sameMedians(List<String> drivers, List<Band> bands) {
        List<String> groups = new ArrayList<>();
        boolean[] told = new boolean[bands.size()];
        for (int i = 0; i < bands.size(); i++) {
            if (told[i]) {
                continue;
            }
            List<String> same = new ArrayList<>(List.of(drivers.get(i)));
            for (int j = i + 1; j < bands.size(); j++) {
                if (!told[j] && Arrays.equals(bands.get(i).xs(), bands.get(j).xs())
                        && Arrays.equals(bands.get(i).median(), bands.get(j).median())) {
                    same.add(drivers.get(j));
                    told[j] = true;
                }
            }
            if (same.size() > 1) {
                groups.add("the medians of " + String.join(", ", same.subList(0, same.size() - 1)) + " and "
                        + same.get(same.size() - 1) + " are the same");
            }
        }
        return String.join("; ", groups);
    }
}
