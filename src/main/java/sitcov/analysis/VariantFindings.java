package sitcov.analysis;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import sitcov.experiment.DriverRun;
import sitcov.experiment.MapId;
import sitcov.experiment.MapRun;
import sitcov.experiment.ReplicationResult;
import sitcov.judge.Detection;
import sitcov.judge.FaultOutcome;
import sitcov.judge.RunSummary;
import sitcov.judge.Variant;
import sitcov.oracle.Failure;
import sitcov.stats.ConfidenceInterval;
import sitcov.stats.McNemar;
import sitcov.stats.Wilson;

/**
 * Each variant against the reference over the distinct maps an experiment judged (a map several
 * drivers of a replication ran counts once): on how many it failed where the reference did not
 * (regressed, the differential oracle's FOUND; with a 95 % Wilson interval and the failures by type),
 * on how many the reference failed where the variant did not fail at all (improved), and McNemar's
 * exact test on those two counts, the maps where only one of them failed.
 */
public record VariantFindings(List<Row> rows) {
    /** One variant's findings; {@code byFailure} counts the first new failure of each regressed map by type. */
    public record Row(Variant variant, long maps, long regressed, ConfidenceInterval regressedShare, long improved,
                      double mcNemarP, Map<Failure, Long> byFailure, List<MapId> firstRegressed) {
    }

    /** How many regressed maps each row names, in the order they were judged. */
    public static final int MAPS_NAMED = 5;

    public VariantFindings {
        rows = List.copyOf(rows);
    }

    public static VariantFindings of(List<ReplicationResult> results, List<Variant> variants) {
        List<MapRun> distinct = new ArrayList<>();
        for (ReplicationResult r : results) {
            Set<MapId> seen = new HashSet<>();
            for (DriverRun d : r.drivers()) {
                for (MapRun m : d.maps()) {
                    if (seen.add(m.map())) {
                        distinct.add(m);
                    }
                }
            }
        }
        List<Row> rows = new ArrayList<>();
        for (int v = 0; v < variants.size(); v++) {
            long regressed = 0;
            long improved = 0;
            Map<Failure, Long> byFailure = new TreeMap<>();
            List<MapId> first = new ArrayList<>();
            for (MapRun m : distinct) {
                FaultOutcome o = m.faults().get(v);
                if (o.detection() == Detection.FOUND) {
                    regressed++;
                    o.newAccident().ifPresent(f -> byFailure.merge(f, 1L, Long::sum));
                    if (first.size() < MAPS_NAMED) {
                        first.add(m.map());
                    }
                } else if (failed(m.faultFree()) && !failed(o.run())) {
                    improved++;
                }
            }
            rows.add(new Row(variants.get(v), distinct.size(), regressed, Wilson.interval(regressed, distinct.size()),
                    improved, McNemar.exactP(regressed, improved), byFailure, first));
        }
        return new VariantFindings(rows);
    }

    private static boolean failed(RunSummary run) {
        return run.hasAccident() || Failure.of(run.outcome()).isPresent();
    }
}
