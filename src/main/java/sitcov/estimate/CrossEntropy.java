package sitcov.estimate;

import java.util.Arrays;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import sitcov.world.DrawSite;
import sitcov.world.Tilt;

/**
 * One step of the multilevel cross-entropy method: from the runs of a stage drawn under the current
 * proposal, the elite — the failures, or while failures are rarer than the elite quantile the runs
 * whose {@link Sample#score} is within that quantile — and the proposal refitted to them by weighted
 * maximum likelihood (a bin's probability ∝ Σ over elite runs of w·draws in the bin), smoothed
 * towards the current proposal and mixed with the generator (a defensive share, which bounds every
 * draw's weight).
 */
public final class CrossEntropy {
    private CrossEntropy() {
    }

    /** The proposal fitted, the score level that made the elite, and the elite's size. */
    public record Fit(Tilt tilt, double level, int elite) {
    }

    public static Fit refit(Tilt current, List<Sample> stage, Set<DrawSite> sites, double eliteQuantile,
                            double smoothing, double defensive) {
        double[] scores = stage.stream().mapToDouble(Sample::score).sorted().toArray();
        if (scores.length == 0) {
            return new Fit(current, Double.NaN, 0);
        }
        int rank = Math.max(0, (int) Math.ceil(eliteQuantile * scores.length) - 1);
        double level = scores[rank];
        Map<DrawSite, double[]> fitted = new EnumMap<>(DrawSite.class);
        int elite = 0;
        for (Sample s : stage) {
            if (s.score() > level) {
                continue;
            }
            elite++;
            double w = s.weight();
            for (DrawSite site : sites) {
                double[] mass = fitted.computeIfAbsent(site, x -> new double[x.bins()]);
                for (int b = 0; b < site.bins(); b++) {
                    mass[b] += w * s.trace().draws(site, b);
                }
            }
        }
        Map<DrawSite, double[]> next = new EnumMap<>(DrawSite.class);
        for (DrawSite site : sites) {
            double[] mass = fitted.get(site);
            double sum = mass == null ? 0 : Arrays.stream(mass).sum();
            double[] q = new double[site.bins()];
            for (int b = 0; b < q.length; b++) {
                double old = current.probability(site, b);
                double fit = sum > 0 ? mass[b] / sum : old;
                q[b] = (1 - defensive) * (smoothing * fit + (1 - smoothing) * old) + defensive / site.bins();
            }
            next.put(site, q);
        }
        return new Fit(Tilt.of(next), level, elite);
    }
}
