package sitcov.experiment;

import java.util.List;
import java.util.Map;
import java.util.Optional;
import sitcov.vehicles.CommandLog;
import sitcov.world.WorldMap;

/** What an experiment tells its listeners, in the order it happens (within a replication). */
public sealed interface ExperimentEvent {
    /** Before anything runs: the replications this run (or shard) will do, and how much was journaled before. */
    record Started(ExperimentConfig config, Shard shard, List<PlannedReplication> replications, int threads,
                   int journaledMaps) implements ExperimentEvent {
        public Started {
            replications = List.copyOf(replications);
        }
    }

    /**
     * A map was judged ({@code resumed}: replayed from the journal, not simulated again). The
     * situation is present when a driver built it (a generated map is fixed by its seed). {@code share}
     * is how much of its budget the driver has spent, 0..1. {@code recordings} are the commands of the
     * map's runs to record ({@link MapRun#recorded}), by run: 0 the reference, i variant i (none when resumed).
     */
    record MapJudged(MapRun run, Optional<WorldMap> builtSituation, boolean resumed, long mapNanos, long driverNanos,
                     int driverIndex, double share, Map<Integer, CommandLog> recordings) implements ExperimentEvent {
        public MapJudged {
            recordings = Map.copyOf(recordings);
        }

        /** A judged map whose runs' commands are not at hand. */
        public MapJudged(MapRun run, Optional<WorldMap> builtSituation, boolean resumed, long mapNanos, long driverNanos,
                         int driverIndex, double share) {
            this(run, builtSituation, resumed, mapNanos, driverNanos, driverIndex, share, Map.of());
        }
    }

    /** A driver finished its share of a replication. */
    record DriverDone(DriverSpend spend, int driverIndex, boolean resumed, long driverNanos) implements ExperimentEvent {
    }

    /** Every driver of a replication finished. */
    record ReplicationDone(int replication) implements ExperimentEvent {
    }

    /** Every replication of the run (or shard) finished. */
    record Ended(ExperimentConfig config, Shard shard) implements ExperimentEvent {
    }
}
