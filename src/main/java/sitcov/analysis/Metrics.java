package sitcov.analysis;

import java.util.List;
import sitcov.experiment.MapRun;
import sitcov.experiment.Measure;
import sitcov.judge.Variant;
import sitcov.judge.FaultOutcome;
import sitcov.judge.Notion;

/**
 * The paper's measures over the maps one method ran in one replication (§5.1 of the paper), under
 * one detection notion: maps run, distinct coverage cells they fill, method-prop-fault (share of the faults found on at least one map),
 * prop-map-all-fault (share of maps finding every fault), avg-map-fault (faults found per map), and
 * per fault the share of maps finding it (Table 2).
 */
public record Metrics(int maps, int cells, double methodPropFault, double propMapAllFault, double avgMapFault, double[] perFault) {
    public Metrics {
        perFault = perFault.clone();
    }

    @Override
    public double[] perFault() {
        return perFault.clone();
    }

    /** Distinct faults found on at least one map. */
    public int faultsFound() {
        int n = 0;
        for (double p : perFault) {
            n += p > 0 ? 1 : 0;
        }
        return n;
    }

    /** The value of {@code measure} for these maps, with {@code area} the area under their discovery curve. */
    double value(Measure measure, double area) {
        return switch (measure) {
            case CELLS_COVERED -> cells;
            case MAPS_RUN -> maps;
            case FAULTS_FOUND -> faultsFound();
            case AVG_MAP_FAULT -> avgMapFault;
            case PROP_MAP_ALL_FAULT -> propMapAllFault;
            case DISCOVERY_AREA -> area;
            case OWN_FAILURES, DISTINCT_OWN_FAILURES -> throw new IllegalArgumentException(measure.key()
                    + " counts the reference's own failures: see OwnFailures");
        };
    }

    public static Metrics of(List<MapRun> runs, List<Variant> faults, Notion notion) {
        int n = runs.size();
        int k = faults.size();
        int[] found = new int[k];
        int allFound = 0;
        long total = 0;
        for (MapRun run : runs) {
            int onMap = 0;
            for (int f = 0; f < k; f++) {
                FaultOutcome v = run.faults().get(f);
                if (!v.variant().equals(faults.get(f))) {
                    throw new IllegalArgumentException("faults of map " + run.map().text() + " are not in fault order");
                }
                boolean hit = v.found(notion);
                if (hit) {
                    found[f]++;
                    onMap++;
                }
            }
            total += onMap;
            allFound += onMap == k && k > 0 ? 1 : 0;
        }
        int faultsFoundAnywhere = 0;
        double[] perFault = new double[k];
        for (int f = 0; f < k; f++) {
            faultsFoundAnywhere += found[f] > 0 ? 1 : 0;
            perFault[f] = n == 0 ? 0 : (double) found[f] / n;
        }
        int cells = (int) runs.stream().mapToInt(MapRun::cell).filter(c -> c >= 0).distinct().count();
        return new Metrics(n, cells, k == 0 ? 0 : (double) faultsFoundAnywhere / k, n == 0 ? 0 : (double) allFound / n,
                n == 0 ? 0 : (double) total / n, perFault);
    }
}
