package sitcov.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import sitcov.coverage.GridDefinition;
import sitcov.experiment.BudgetKind;
import sitcov.experiment.DriverSpend;
import sitcov.experiment.ExperimentConfig;
import sitcov.experiment.ExperimentEvent;
import sitcov.experiment.MapId;
import sitcov.experiment.MapRun;
import sitcov.experiment.Shard;
import sitcov.experiment.StopReason;
import sitcov.faults.FaultSet;
import sitcov.judge.RunSummary;
import sitcov.oracle.Outcome;

class ProgressListenerTest {
    private static final ExperimentConfig CONFIG = new ExperimentConfig("eta", 1, 10, 3, FaultSet.parse("19"),
            BudgetKind.TICKS, GridDefinition.paper());
    private static final long S = 1_000_000_000L;

    private final long[] now = {0};
    private final ByteArrayOutputStream err = new ByteArrayOutputStream();
    private final ProgressListener progress = new ProgressListener(new PrintStream(err, true, StandardCharsets.UTF_8),
            false, () -> now[0]);

    private static ExperimentEvent.MapJudged map(int replication, int driver, double share, long seconds) {
        RunSummary safe = new RunSummary(Outcome.TARGET_REACHED, 10, List.of(0L, 0L, 0L, 0L, 0L));
        MapRun run = new MapRun(replication, CONFIG.drivers().get(driver), 0, 0, new MapId.Seeded(1), 1, 1, 0,
                List.of(0.0, 0.0, 0.0), safe, List.of());
        return new ExperimentEvent.MapJudged(run, Optional.empty(), false, S, seconds * S, driver, share);
    }

    private static ExperimentEvent.DriverDone done(int replication, int driver, long seconds) {
        return new ExperimentEvent.DriverDone(new DriverSpend(replication, CONFIG.drivers().get(driver), 10, 1, 10, 1,
                StopReason.CANDIDATES), driver, false, seconds * S);
    }

    @Test
    void theEtaDealsTheReplicationsLeftToTheThreadsThatFreeUpFirst() {
        progress.on(new ExperimentEvent.Started(CONFIG, Shard.WHOLE, CONFIG.plan(), 2, 0));
        assertTrue(Double.isNaN(progress.eta(now[0])), "nothing tells how long a driver takes yet");
        // replications 0 and 1 start together; the filter of replication 0 is a quarter done after 10 s
        now[0] = 10 * S;
        progress.on(map(0, 0, 0.25, 10));
        progress.on(map(1, 0, 0.25, 10));
        // a driver's share takes 40 s (10 s / 0.25), the second driver as long as the first: each
        // running replication has 30 + 40 s left, and replication 2 then takes 80 s on a free thread
        assertEquals(70 + 80, progress.eta(now[0]), 1e-9);
        // at 40 s both filters are done in 40 s; the random drivers start
        now[0] = 40 * S;
        progress.on(done(0, 0, 40));
        progress.on(done(1, 0, 40));
        assertEquals(40 + 80, progress.eta(now[0]), 1e-9);
    }

    @Test
    void progressIsReportedWithTheMapsJudgedLongBeforeAReplicationEnds() {
        progress.on(new ExperimentEvent.Started(CONFIG, Shard.WHOLE, CONFIG.plan(), 2, 0));
        now[0] = 16 * S;
        progress.on(map(0, 0, 0.5, 16));
        String text = err.toString(StandardCharsets.UTF_8);
        assertTrue(text.contains("0/3 replications done, 1 maps judged, 16 s elapsed, ETA"), text);
    }

    @Test
    void whileAResumedRunReplaysItsJournalTheEtaIsStillBeingEstimated() {
        progress.on(new ExperimentEvent.Started(CONFIG, Shard.WHOLE, CONFIG.plan(), 2, 5));
        ExperimentEvent.MapJudged live = map(0, 0, 0.25, 10);
        ExperimentEvent.MapJudged replayed = new ExperimentEvent.MapJudged(live.run(), Optional.empty(), true, S, 10 * S,
                0, 0.25);
        progress.on(replayed);
        assertTrue(Double.isNaN(progress.eta(now[0])), "the replayed journal's times say nothing of this machine");
        now[0] = 10 * S;
        progress.on(live);
        assertTrue(Double.isFinite(progress.eta(now[0])));
    }
}
