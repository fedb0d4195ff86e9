package sitcov.experiment;

import java.util.List;
import sitcov.judge.FaultOutcome;
import sitcov.judge.Notion;
import sitcov.judge.RunSummary;

/**
 * One map a driver ran in one replication, as the results folder keeps it: which driver, its
 * {@code mapIndex}-th map, drawn as candidate {@code candidate} of the replication's stream (for a
 * situation a driver built, the candidate it was built in place of, or -1), the map, both seeds, its cell and criteria, the fault-free run and every fault's outcome.
 */
public record MapRun(int replication, String driver, int mapIndex, int candidate, MapId map, long externalSeed,
                     long internalSeed, int cell, List<Double> criteria, RunSummary faultFree, List<FaultOutcome> faults) {
    public MapRun {
        criteria = List.copyOf(criteria);
        faults = List.copyOf(faults);
    }

    /** Simulated ticks this map cost: the fault-free run and every faulty run. */
    public long ticks() {
        return faultFree.ticks() + faults.stream().mapToLong(f -> f.run().ticks()).sum();
    }

    /**
     * Which runs of this map a results folder lists as a failure or a finding, and so records: the
     * reference's run where it failed by itself (an accident, a TIMEOUT or its controller's failure), and
     * each variant's run that was found or whose controller failed; the reference's run goes with any of
     * them, as the twin a variant is judged against. Index 0 is the reference, then each variant in order.
     */
    public boolean[] recorded() {
        boolean[] kept = new boolean[1 + faults.size()];
        boolean any = failed(faultFree);
        for (int i = 0; i < faults.size(); i++) {
            FaultOutcome f = faults.get(i);
            kept[1 + i] = f.detection().found() || sitcov.oracle.Failure.of(f.run().outcome()).isPresent();
            any |= kept[1 + i];
        }
        kept[0] = any;
        return kept;
    }

    private static boolean failed(RunSummary run) {
        return run.hasAccident() || sitcov.oracle.Failure.of(run.outcome()).isPresent();
    }

    /** Faults found on this map, by the differential oracle or by the paper's notion. */
    public long faultsFound(Notion notion) {
        return faults.stream().filter(f -> f.found(notion)).count();
    }
}
