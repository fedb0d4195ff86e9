package sitcov.analysis;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import sitcov.experiment.DriverKey;
import sitcov.experiment.DriverRun;
import sitcov.experiment.ExperimentConfig;
import sitcov.experiment.MapRun;
import sitcov.experiment.ReplicationResult;
import sitcov.judge.Variant;
import sitcov.judge.Notion;

/**
 * The paper's measures of an experiment, computed once: per replication, driver and detection
 * notion ({@link Metrics}), and their means over replications, which the printed table, the CSV
 * files and the figures all read from here.
 */
public final class Summary {
    /** The means over replications of one driver under one notion; {@code perFault} in fault id order. */
    public record Mean(String driver, Notion notion, double maps, double cells, double methodPropFault,
                       double propMapAllFault, double avgMapFault, double[] perFault) {
        public Mean {
            perFault = perFault.clone();
        }

        @Override
        public double[] perFault() {
            return perFault.clone();
        }
    }

    private final List<Variant> faults;
    private final List<String> drivers;
    private final List<ReplicationResult> results;
    /** The metrics of each replication, driver and notion. */
    private final Map<Key, Metrics> metrics = new LinkedHashMap<>();

    private record Key(DriverKey driver, Notion notion) {
    }

    public Summary(ExperimentConfig config, List<ReplicationResult> results) {
        this.faults = config.variants();
        this.drivers = config.drivers();
        this.results = List.copyOf(results);
        for (ReplicationResult r : results) {
            for (DriverRun d : r.drivers()) {
                for (Notion notion : Notion.values()) {
                    metrics.put(new Key(new DriverKey(r.replication(), d.driver()), notion), Metrics.of(d.maps(), faults, notion));
                }
            }
        }
    }

    public List<Variant> faults() {
        return faults;
    }

    public List<String> drivers() {
        return drivers;
    }

    public List<ReplicationResult> results() {
        return results;
    }

    public Metrics metrics(int replication, String driver, Notion notion) {
        Metrics m = metrics.get(new Key(new DriverKey(replication, driver), notion));
        if (m == null) {
            throw new IllegalArgumentException("no results of driver " + driver + " in replication " + replication);
        }
        return m;
    }

    /**
     * The cells ever seen: those any driver covered in any replication. With a coverage-filter
     * driver, which runs the first candidate of every cell it meets, that is every cell its
     * replications' random candidates reached (600 000 candidates in {@code mature-rq1}): coverage
     * is reported of these reachable cells beside the grid's total.
     */
    public int cellsSeen() {
        java.util.Set<Integer> seen = new java.util.HashSet<>();
        for (ReplicationResult r : results) {
            for (DriverRun d : r.drivers()) {
                d.maps().stream().mapToInt(MapRun::cell).filter(c -> c >= 0).forEach(seen::add);
            }
        }
        return seen.size();
    }

    /** The means over every replication of one driver under one notion. */
    public Mean mean(String driver, Notion notion) {
        List<Metrics> all = new ArrayList<>();
        for (ReplicationResult r : results) {
            all.add(metrics(r.replication(), driver, notion));
        }
        int n = Math.max(1, all.size());
        double[] perFault = new double[faults.size()];
        double maps = 0;
        double cells = 0;
        double prop = 0;
        double allFault = 0;
        double avg = 0;
        for (Metrics m : all) {
            maps += m.maps();
            cells += m.cells();
            prop += m.methodPropFault();
            allFault += m.propMapAllFault();
            avg += m.avgMapFault();
            double[] p = m.perFault();
            for (int f = 0; f < perFault.length; f++) {
                perFault[f] += p[f];
            }
        }
        for (int f = 0; f < perFault.length; f++) {
            perFault[f] /= n;
        }
        return new Mean(driver, notion, maps / n, cells / n, prop / n, allFault / n, avg / n, perFault);
    }
}
