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
