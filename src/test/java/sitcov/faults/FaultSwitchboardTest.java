package sitcov.faults;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Set;
import org.junit.jupiter.api.Test;

class FaultSwitchboardTest {
    private long tick;

    @Test
    void aShadowingBoardSwitchesNothingOnAndNotesWhenEachWatchedFaultWouldFirstBeReachedAndDepart() {
        FaultSwitchboard board = FaultSwitchboard.shadowing(Set.of(Fault.ONCOMING_AT_HALF_SPEED, Fault.CREEPS_WHILE_WAITING),
                () -> tick);
        assertFalse(board.isActive(Fault.ONCOMING_AT_HALF_SPEED));
        assertTrue(board.watches(Fault.ONCOMING_AT_HALF_SPEED));
        assertFalse(board.watches(Fault.SECOND_PULL_OUT), "a fault not watched is not asked for");
        tick = 4;
        board.reached(Fault.ONCOMING_AT_HALF_SPEED);
        tick = 9;
        board.reached(Fault.ONCOMING_AT_HALF_SPEED);
        board.effective(Fault.ONCOMING_AT_HALF_SPEED);
        tick = 12;
        board.effective(Fault.ONCOMING_AT_HALF_SPEED);
        assertEquals(new Shadow(Fault.ONCOMING_AT_HALF_SPEED, 4, 9), board.shadow(Fault.ONCOMING_AT_HALF_SPEED));
        assertFalse(board.watches(Fault.ONCOMING_AT_HALF_SPEED), "once departed, its shadow is no longer worked out");
        assertEquals(new Shadow(Fault.CREEPS_WHILE_WAITING, -1, -1), board.shadow(Fault.CREEPS_WHILE_WAITING));
        // and nothing was recorded as the run's own activity
        assertEquals(new Activation(Fault.ONCOMING_AT_HALF_SPEED, false, false, 0, -1),
                board.activation(Fault.ONCOMING_AT_HALF_SPEED));
    }

    @Test
    void aShadowThatNeverDepartsGivesTheActivationOfAFaultReachedWithoutEffect() {
        Shadow reached = new Shadow(Fault.SECOND_PULL_OUT, 30, -1);
        assertEquals(new Activation(Fault.SECOND_PULL_OUT, true, true, 0, -1), reached.activation());
        assertTrue(reached.reachedBefore(31));
        assertFalse(reached.reachedBefore(30), "reached in the departure tick itself is the forked run's to record");
    }

    @Test
    void aForkedRunsBoardCarriesOverWhetherTheFaultWasReachedAndCountsEffectsFromTheFork() {
        FaultSwitchboard board = new FaultSwitchboard(Set.of(), () -> tick);
        tick = 50;
        board.switchOn(Fault.CREEPS_WHILE_WAITING, true);
        assertTrue(board.isActive(Fault.CREEPS_WHILE_WAITING));
        board.effective(Fault.CREEPS_WHILE_WAITING);
        assertEquals(new Activation(Fault.CREEPS_WHILE_WAITING, true, true, 1, 50), board.activation(Fault.CREEPS_WHILE_WAITING));
        board.switchOn(Fault.SECOND_PULL_OUT, false);
        assertTrue(board.isActive(Fault.SECOND_PULL_OUT), "a version with several faults planted has them all on");
        FaultSwitchboard watching = FaultSwitchboard.shadowing(Set.of(Fault.SECOND_PULL_OUT), () -> tick);
        assertThrows(IllegalStateException.class, () -> watching.switchOn(Fault.SECOND_PULL_OUT, false),
                "a run watching from the shadows is the fault-free run of record: nothing is switched on in it");
    }
}
