package sitcov.judge;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import sitcov.builtin.BuiltinRuns;
import sitcov.faults.Fault;
import sitcov.world.MapGenerator;

/** The paper's notion (§5.2): a fault counts where it "was triggered and apparently led to an accident". */
class PaperNotionTest {
    @Test
    void anAccidentInARunWhoseFaultNeverRanDoesNotCount() {
        // map 147's fault-free run clashes with a parked car; fault 5 never runs there (the car never
        // crawls from below the crawl band), so its faulty run is the fault-free run, accident and all
        FaultVerdict v = BuiltinRuns.judge(MapGenerator.generate(147), 147, List.of(Fault.CRAWL_DOUBLE_ACCELERATION))
                .verdicts().get(0);
        assertFalse(v.reached(), v.toString());
        assertTrue(v.faultyRun().hasAccident(), v.toString());
        assertFalse(v.foundByPaperNotion(), v.toString());
        assertFalse(FaultOutcome.of(v).found(Notion.PAPER), v.toString());
    }

    @Test
    void anAccidentInARunWhoseFaultRanCounts() {
        FaultVerdict v = BuiltinRuns.judge(MapGenerator.generate(1), 1, List.of(Fault.WAYPOINTS_NORTH_EAST)).verdicts().get(0);
        assertTrue(v.reached(), v.toString());
        assertTrue(v.faultyRun().hasAccident(), v.toString());
        assertTrue(v.foundByPaperNotion(), v.toString());
        assertTrue(FaultOutcome.of(v).found(Notion.PAPER), v.toString());
    }

    @Test
    void aFolderWrittenBeforeTheNotionAskedForReachedIsReadByTheNotion() {
        // such folders hold "the faulty run had an accident" as paper_found, even where the fault never ran
        RunSummary crashed = new RunSummary(sitcov.oracle.Outcome.TARGET_REACHED, 300, List.of(1L, 0L, 0L, 0L, 0L));
        FaultOutcome notReached = new FaultOutcome(new sitcov.judge.Variant.Seeded(Fault.CRAWL_DOUBLE_ACCELERATION), crashed, false, false, -1,
                Detection.NOT_REACHED, Optional.empty(), true);
        FaultOutcome reached = new FaultOutcome(new sitcov.judge.Variant.Seeded(Fault.CRAWL_DOUBLE_ACCELERATION), crashed, true, false, -1,
                Detection.REACHED_NO_EFFECT, Optional.empty(), true);
        assertEquals(List.of(false, true), List.of(notReached.found(Notion.PAPER), reached.found(Notion.PAPER)));
    }
}
