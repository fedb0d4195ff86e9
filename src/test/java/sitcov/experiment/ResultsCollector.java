package sitcov.experiment;

import sitcov.builtin.BuiltinCar;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * A listener that keeps an experiment's results in memory, for experiments run from code (and
 * tests): every driver's maps and spend, per replication, in the preset's driver order.
 */
public final class ResultsCollector implements ExperimentListener {
    private final Map<String, List<MapRun>> maps = new HashMap<>();
    private final Map<String, DriverSpend> spends = new HashMap<>();
    private List<PlannedReplication> replications = List.of();
    private List<String> drivers = List.of();

    @Override
    public void on(ExperimentEvent event) {
        if (event instanceof ExperimentEvent.Started s) {
            replications = s.replications();
            drivers = s.config().drivers();
        } else if (event instanceof ExperimentEvent.MapJudged m) {
            maps.computeIfAbsent(m.run().replication() + "/" + m.run().driver(), k -> new ArrayList<>()).add(m.run());
        } else if (event instanceof ExperimentEvent.DriverDone d) {
            spends.put(d.spend().replication() + "/" + d.spend().driver(), d.spend());
        }
    }

    /** The replications whose every driver finished, in plan order. */
    public List<ReplicationResult> results() {
        List<ReplicationResult> results = new ArrayList<>();
        for (PlannedReplication p : replications) {
            List<DriverRun> runs = new ArrayList<>();
            for (String d : drivers) {
                String key = p.index() + "/" + d;
                if (spends.containsKey(key)) {
                    runs.add(new DriverRun(d, maps.getOrDefault(key, List.of()), spends.get(key)));
                }
            }
            if (runs.size() == drivers.size()) {
                results.add(new ReplicationResult(p.index(), runs));
            }
        }
        return results;
    }

    /** Runs {@code config} whole on {@code threads} threads and returns its results. */
    public static List<ReplicationResult> run(ExperimentConfig config, DriverFactory drivers, int threads) {
        ResultsCollector collector = new ResultsCollector();
        new ExperimentRunner(config, drivers, Shard.WHOLE, Journal.empty(), threads, System::nanoTime, List.of(collector), BuiltinCar.SOURCE)
                .run();
        return collector.results();
    }
}
