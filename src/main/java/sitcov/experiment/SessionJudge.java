package sitcov.experiment;

import java.util.function.Supplier;
import sitcov.world.WorldMap;

/**
 * How a driver's session gets a map judged: {@link FreshJudge} simulates it (or takes it from another
 * driver of the replication that judged it), {@link JournalReplay} reads it back from the journal of a
 * resumed run, so the session ends exactly where an uninterrupted run would.
 */
sealed interface SessionJudge permits FreshJudge, JournalReplay {
    /** The session's map number {@code index}: what it is, where it lies in the grid, and how to build it. */
    record Request(int index, MapId id, int candidate, double[] criteria, int cell, Supplier<WorldMap> map) {
    }

    /**
     * A judged map, whether it came from the journal, the wall time charged for it and the driver's time
     * after it, and the commands of its runs to record, by run (none when it came from the journal).
     */
    record Judgement(MapRun run, boolean replayed, long mapNanos, long driverNanos,
                     java.util.Map<Integer, sitcov.vehicles.CommandLog> recordings) {
    }

    Judgement judge(Request request);
}
