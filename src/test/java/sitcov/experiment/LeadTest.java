package sitcov.experiment;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.CompletableFuture;
import org.junit.jupiter.api.Test;

/** A later driver beside the first stops where it would have stopped after it. */
class LeadTest {
    private static final Runnable NO_HALT = () -> { };

    @Test
    void aLaterDriverBehindTheFirstDrawsOnWithoutWaiting() {
        Lead lead = new Lead();
        lead.spent(1000);
        assertTrue(lead.ticksLeft(999, NO_HALT), "the first's total can only be 1000 or more");
    }

    @Test
    void aLaterDriverThatCaughtUpWaitsForTheFirstToSpendMoreOrToFinish() throws Exception {
        Lead lead = new Lead();
        lead.spent(500);
        CompletableFuture<Boolean> waiting = CompletableFuture.supplyAsync(() -> lead.ticksLeft(600, NO_HALT));
        lead.spent(700);
        assertTrue(waiting.get(), "the first spent 700 > 600: draw on");

        CompletableFuture<Boolean> atTheEnd = CompletableFuture.supplyAsync(() -> lead.ticksLeft(800, NO_HALT));
        lead.finished(800, 123);
        assertFalse(atTheEnd.get(), "the first finished at 800: a driver with 800 is done, as it would be after it");
        assertTrue(lead.ticksLeft(799, NO_HALT));
        assertEquals(800, lead.ticksSoFar());
    }

    @Test
    void underTheWallClockALaterDriverRunsWhileTheFirstRunsThenToItsTime() {
        Lead lead = new Lead();
        assertTrue(lead.nanosLeft(10_000_000_000L), "the first is still running");
        lead.finished(42, 5_000);
        assertTrue(lead.nanosLeft(4_999));
        assertFalse(lead.nanosLeft(5_000));
    }

    @Test
    void aFirstDriverThatStoppedWithoutFinishingLeavesNobodyWaiting() throws Exception {
        Lead lead = new Lead();
        CompletableFuture<Boolean> waiting = CompletableFuture.supplyAsync(() -> lead.ticksLeft(0, NO_HALT));
        lead.abandoned();
        Exception e = assertThrows(Exception.class, waiting::get);
        assertTrue(e.getCause() instanceof IllegalStateException, e.toString());
    }
}
