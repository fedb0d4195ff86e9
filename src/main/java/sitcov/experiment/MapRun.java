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

    /** Faults found on this map, by the differential oracle or by the paper's notion. */
    public long faultsFound(Notion notion) {
        return faults.stream().filter(f -> f.found(notion)).count();
    }
}
