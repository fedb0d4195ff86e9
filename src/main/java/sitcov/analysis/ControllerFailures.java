package sitcov.analysis;

import java.util.ArrayList;
import java.util.List;
import sitcov.experiment.DriverRun;
import sitcov.experiment.MapRun;
import sitcov.experiment.ReplicationResult;
import sitcov.judge.FaultOutcome;
import sitcov.judge.Variant;
import sitcov.oracle.Failure;

/**
 * How often the controllers themselves failed over an experiment's judged maps (no command in time,
 * an exit, garbage): the reference's runs, and each variant's. A controller that failed on every map
 * drove nowhere, so nothing else the experiment measured says anything about driving.
 */
public record ControllerFailures(long maps, Count reference, List<VariantCount> variants) {
    /** Runs that ended in each kind of controller failure. */
    public record Count(long timeouts, long errors) {
        public long total() {
            return timeouts + errors;
        }
    }

    /** One variant's count. */
    public record VariantCount(Variant variant, Count count) {
    }

    public ControllerFailures {
        variants = List.copyOf(variants);
    }

    public static ControllerFailures of(List<ReplicationResult> results, List<Variant> variants) {
        long maps = 0;
        long[] ref = new long[2];
        long[][] var = new long[variants.size()][2];
        for (ReplicationResult r : results) {
            for (DriverRun d : r.drivers()) {
                for (MapRun m : d.maps()) {
                    maps++;
                    count(ref, Failure.of(m.faultFree().outcome()).orElse(null));
                    List<FaultOutcome> outcomes = m.faults();
                    for (int v = 0; v < outcomes.size(); v++) {
                        count(var[v], Failure.of(outcomes.get(v).run().outcome()).orElse(null));
                    }
                }
            }
        }
        List<VariantCount> counts = new ArrayList<>();
        for (int v = 0; v < variants.size(); v++) {
            counts.add(new VariantCount(variants.get(v), new Count(var[v][0], var[v][1])));
        }
        return new ControllerFailures(maps, new Count(ref[0], ref[1]), counts);
    }

    private static void count(long[] into, Failure f) {
        if (f == Failure.CONTROLLER_TIMEOUT) {
            into[0]++;
        } else if (f == Failure.CONTROLLER_ERROR) {
            into[1]++;
        }
    }

    /** Whether the reference's controller failed on every map judged (and there was one). */
    public boolean referenceAlwaysFailed() {
        return maps > 0 && reference.total() == maps;
    }

    /** Whether any controller failed anywhere. */
    public boolean any() {
        return reference.total() > 0 || variants.stream().anyMatch(v -> v.count().total() > 0);
    }
}
