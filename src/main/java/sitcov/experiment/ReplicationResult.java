package sitcov.experiment;

import java.util.List;

/**
 * Everything one replication produced: the maps each driver ran (in order), the coverage curve,
 * and the wall time each map took (kept apart: timings never reach the reproducible results).
 */
public record ReplicationResult(int replication, List<MapRun> runs, List<CurvePoint> curve, List<Long> mapNanos,
                                long coverageNanos, long randomNanos, int randomCandidates) {
    public ReplicationResult {
        runs = List.copyOf(runs);
        curve = List.copyOf(curve);
        mapNanos = List.copyOf(mapNanos);
    }

    public List<MapRun> runsOf(Method method) {
        return runs.stream().filter(r -> r.method() == method).toList();
    }
}
