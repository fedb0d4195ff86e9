package sitcov.experiment;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import sitcov.coverage.GridDefinition;
import sitcov.faults.FaultSet;
import sitcov.judge.FaultyRuns;

/** A replication's first driver leads with its candidates; the others follow in the experiment's kind of budget. */
class ReplicationPlanTest {
    private static final Runnable NO_HALT = () -> { };

    private static ReplicationPlan plan(BudgetKind kind) {
        ExperimentConfig config = new ExperimentConfig("plan", 5, 12, 1, FaultSet.parse("19"), kind,
                GridDefinition.paper(), List.of("lead", "second", "third"), List.of(), 40, FaultyRuns.UNTIL_VERDICT);
        return new ReplicationPlan(config.plan().get(0), config);
    }

    private static Journal.Finished leaderDone(long ticks, long nanos) {
        return new Journal.Finished(new DriverSpend(0, "lead", 12, 3, ticks, 2, StopReason.CANDIDATES), nanos);
    }

    /** A map of 100 ticks fault-free and 50 with fault 19, which the faulty run found or did not. */
    private static MapRun map(boolean found) {
        List<Long> none = java.util.Collections.nCopies(sitcov.oracle.AccidentType.values().length, 0L);
        sitcov.judge.RunSummary faultFree = new sitcov.judge.RunSummary(sitcov.oracle.Outcome.TARGET_REACHED, 100, none);
        sitcov.judge.RunSummary faulty = new sitcov.judge.RunSummary(sitcov.oracle.Outcome.STOPPED_AT_VERDICT, 50, none);
        sitcov.judge.FaultOutcome outcome = new sitcov.judge.FaultOutcome(new sitcov.judge.Variant.Seeded(sitcov.faults.Fault.ofId(19)), faulty, true, true,
                3, found ? sitcov.judge.Detection.FOUND : sitcov.judge.Detection.EFFECT_NO_FAILURE, java.util.Optional.empty(),
                found);
        return new MapRun(0, "second", 0, 0, new MapId.Seeded(1), 1, 2, 0, List.of(), faultFree, List.of(outcome));
    }

    @Test
    void inACampaignsTrialNoDriverLeadsAndEachSpendsTheFixedTicksUntilItsFirstFind() {
        ExperimentConfig config = new ExperimentConfig("trial", 5, 40, 1, ExperimentConfig.seeded(FaultSet.parse("19")), BudgetKind.FIXED_TICKS,
                GridDefinition.paper(), List.of("first", "second"), List.of(), 40, FaultyRuns.UNTIL_VERDICT,
                AnalysisPlan.defaults(List.of("first", "second")), ExperimentConfig.BUILTIN, 300);
        ReplicationPlan plan = new ReplicationPlan(config.plan().get(0), config);
        assertFalse(plan.leads(0), "no driver leads a trial");
        Budget first = plan.budget(0);
        Budget second = plan.budget(1);
        assertInstanceOf(Budget.FixedTicks.class, first);
        assertEquals(40, first.candidateLimit());
        first.judged(map(false));
        assertTrue(first.left(299, 0, NO_HALT), "below its 300 ticks, no find yet");
        assertFalse(first.left(300, 0, NO_HALT), "its ticks are spent");
        assertEquals(StopReason.TICKS, first.spentOut());
        second.judged(map(true));
        assertFalse(second.left(150, 0, NO_HALT), "a map found the fault: the trial is falsified");
        assertEquals(StopReason.FALSIFIED, second.spentOut());
        assertTrue(first.left(10, 0, NO_HALT), "one driver's find does not stop another");
    }

    @Test
    void aTickBudgetGoesOnlyWithACampaignsTrialOfOneFault() {
        assertThrows(IllegalArgumentException.class, () -> new ExperimentConfig("t", 5, 40, 1, ExperimentConfig.seeded(FaultSet.parse("19")),
                BudgetKind.TICKS, GridDefinition.paper(), List.of("a"), List.of(), 40, FaultyRuns.UNTIL_VERDICT,
                AnalysisPlan.defaults(List.of("a")), ExperimentConfig.BUILTIN, 300));
        assertThrows(IllegalArgumentException.class, () -> new ExperimentConfig("t", 5, 40, 1, ExperimentConfig.seeded(FaultSet.parse("18,19")),
                BudgetKind.FIXED_TICKS, GridDefinition.paper(), List.of("a"), List.of(), 40, FaultyRuns.UNTIL_VERDICT,
                AnalysisPlan.defaults(List.of("a")), ExperimentConfig.BUILTIN, 300));
        assertThrows(IllegalArgumentException.class, () -> new ExperimentConfig("t", 5, 40, 1, ExperimentConfig.seeded(FaultSet.parse("19")),
                BudgetKind.FIXED_TICKS, GridDefinition.paper(), List.of("a"), List.of(), 40, FaultyRuns.UNTIL_VERDICT,
                AnalysisPlan.defaults(List.of("a")), ExperimentConfig.BUILTIN, 0));
    }

    @Test
    void theFirstDriverLeadsWithTheReplicationsCandidates() {
        ReplicationPlan plan = plan(BudgetKind.TICKS);
        assertTrue(plan.leads(0));
        assertFalse(plan.leads(1));
        Budget.Candidates lead = assertInstanceOf(Budget.Candidates.class, plan.budget(0));
        assertEquals(12, lead.count());
        assertEquals(12, lead.candidateLimit(), "the leader's candidates are its limit too");
        assertEquals(StopReason.CANDIDATES, lead.atLimit());
        assertEquals(0.25, lead.share(3, 999, 999), 1e-12, "3 of 12 candidates, whatever the ticks and time");
    }

    @Test
    void laterDriversFollowInTheExperimentsKindOfBudgetUpToTheCandidateLimit() {
        Budget ticks = plan(BudgetKind.TICKS).budget(1);
        Budget wall = plan(BudgetKind.WALL_CLOCK).budget(2);
        assertInstanceOf(Budget.TicksOfLead.class, ticks);
        assertInstanceOf(Budget.WallClockOfLead.class, wall);
        assertEquals(40, ticks.candidateLimit());
        assertEquals(StopReason.CANDIDATE_LIMIT, ticks.atLimit());
        assertEquals(StopReason.TICKS, ticks.spentOut());
        assertEquals(StopReason.WALL_CLOCK, wall.spentOut());
    }

    @Test
    void aFollowerSpendsTheTicksTheLeaderSpent() {
        ReplicationPlan plan = plan(BudgetKind.TICKS);
        Budget leader = plan.budget(0);
        Budget follower = plan.budget(1);
        leader.charged(500);
        assertTrue(follower.left(499, 0, NO_HALT), "the leader has spent 500 already");
        assertEquals(0.5, follower.share(0, 250, 0), 1e-12);
        plan.finished(0, leaderDone(600, 7));
        assertTrue(follower.left(599, 0, NO_HALT));
        assertFalse(follower.left(600, 0, NO_HALT), "the leader finished at 600 ticks");
    }

    @Test
    void aFollowerUnderTheWallClockRunsToTheLeadersTime() {
        ReplicationPlan plan = plan(BudgetKind.WALL_CLOCK);
        Budget follower = plan.budget(1);
        assertTrue(follower.left(0, 1_000_000, NO_HALT), "the leader is still running");
        plan.finished(0, leaderDone(600, 2_000));
        assertTrue(follower.left(0, 1_999, NO_HALT));
        assertFalse(follower.left(0, 2_000, NO_HALT));
        assertEquals(0.25, follower.share(0, 0, 500), 1e-12);
    }

    @Test
    void aLeaderThatFailedLeavesItsFollowersAnErrorNotAWait() {
        ReplicationPlan plan = plan(BudgetKind.TICKS);
        Budget follower = plan.budget(1);
        plan.failed(1);
        plan.budget(0).charged(100);
        assertTrue(follower.left(50, 0, NO_HALT), "a follower's failure abandons nothing");
        plan.failed(0);
        assertThrows(IllegalStateException.class, () -> follower.left(50, 0, NO_HALT));
    }

    @Test
    void theReplicationEndsWithItsLastDriverCountedOff() {
        ReplicationPlan plan = plan(BudgetKind.TICKS);
        assertFalse(plan.countOff());
        assertFalse(plan.countOff());
        assertTrue(plan.countOff(), "three drivers, three counted off");
    }
}
