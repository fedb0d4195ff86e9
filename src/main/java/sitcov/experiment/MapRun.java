package sitcov.experiment;

import java.util.List;
import sitcov.oracle.RunResult;

/**
 * One map a driver ran: where it came from (method, replication, candidate index), its seeds, its
 * coverage cell and criteria values, the fault-free run and the verdict on every fault of the set.
 */
public record MapRun(Method method, int replication, int candidate, long externalSeed, long internalSeed, int cell,
                     double[] criteria, RunResult faultFree, List<FaultVerdict> verdicts, long ticks) {
    public MapRun {
        criteria = criteria.clone();
        verdicts = List.copyOf(verdicts);
    }

    @Override
    public double[] criteria() {
        return criteria.clone();
    }

    /** Faults found on this map, by the differential oracle or by the paper's notion. */
    public long faultsFound(boolean paperNotion) {
        return verdicts.stream().filter(v -> paperNotion ? v.foundByPaperNotion() : v.detection().found()).count();
    }
}
