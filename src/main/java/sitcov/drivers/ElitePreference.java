package sitcov.drivers;

import java.util.HashMap;
import java.util.List;
import java.util.Map;
import sitcov.experiment.MapRun;
import sitcov.judge.Variant;
import sitcov.judge.FaultOutcome;
import sitcov.judge.Notion;

/**
 * Which elites a search edits more often: all alike (coverage-search), or those whose maps found
 * faults few other maps found (fault-search). Told of every map the search runs; asked for weights.
 */
interface ElitePreference {
    /** Every elite alike: the search draws its aim evenly. */
    ElitePreference EVEN = new ElitePreference() {
        @Override
        public void ran(int cell, MapRun run) {
        }

        @Override
        public double weight(int cell) {
            return 1;
        }

        @Override
        public boolean even() {
            return true;
        }
    };

    /** The map run for the elite of {@code cell}. */
    void ran(int cell, MapRun run);

    /** How much more often than an elite of weight 1 the elite of {@code cell} is edited. */
    double weight(int cell);

    /** Whether every weight is the same (the search then draws evenly, not by weight). */
    default boolean even() {
        return false;
    }

    /**
     * Elites weighted 1 + {@value #RARITY} × Σ 1 / (maps of this replication that found f), over the
     * faults f their own map found (differential oracle): a map that alone found a fault is edited
     * {@value #RARITY} + 1 times as often as one that found none, in the hope that its neighbours hold
     * the situations where that fault acts.
     */
    final class RareFaults implements ElitePreference {
        static final double RARITY = 10;
        private final Map<Variant, Integer> finds = new HashMap<>();
        private final Map<Integer, List<Variant>> foundIn = new HashMap<>();

        @Override
        public void ran(int cell, MapRun run) {
            List<Variant> found = run.faults().stream().filter(f -> f.found(Notion.DIFFERENTIAL)).map(FaultOutcome::variant).toList();
            foundIn.put(cell, found);
            found.forEach(f -> finds.merge(f, 1, Integer::sum));
        }

        @Override
        public double weight(int cell) {
            double w = 1;
            for (Variant f : foundIn.getOrDefault(cell, List.of())) {
                w += RARITY / finds.get(f);
            }
            return w;
        }
    }
}
