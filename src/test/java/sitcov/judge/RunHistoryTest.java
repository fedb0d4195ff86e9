package sitcov.judge;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Set;
import org.junit.jupiter.api.Test;
import sitcov.builtin.BuiltinCar;
import sitcov.builtin.BuiltinRuns;
import sitcov.faults.Fault;
import sitcov.world.MapGenerator;
import sitcov.world.WorldMap;

class RunHistoryTest {
    private static final WorldMap MAP = MapGenerator.generate(3);

    private static LiveRun steppedTo(long tick) {
        LiveRun run = BuiltinRuns.live(MAP, 5, Set.of(Fault.ONCOMING_AT_HALF_SPEED));
        while (run.tick() < tick) {
            run.step();
        }
        return run;
    }

    private static String pose(LiveRun run) {
        var car = run.telemetry().car();
        return run.tick() + ": " + car.x() + " " + car.y() + " " + car.heading() + " " + car.speed();
    }

    @Test
    void steppingBackAcrossACheckpointGivesTheRunAsItWasThen() {
        RunHistory history = new RunHistory(BuiltinRuns.live(MAP, 5, Set.of(Fault.ONCOMING_AT_HALF_SPEED)));
        long forward = RunHistory.INTERVAL + 3;
        for (long t = 0; t <= forward; t++) {
            assertTrue(history.step());
        }
        for (int back = 1; back <= 6; back++) {
            assertTrue(history.stepBack());
            LiveRun then = steppedTo(forward - back);
            assertEquals(pose(then), pose(history.current()), back + " ticks back");
            assertEquals(then.record(), history.current().record(), back + " ticks back");
        }
        // and on again from there, as the run itself went
        for (int t = 0; t < 10; t++) {
            history.step();
        }
        assertEquals(pose(steppedTo(forward - 6 + 10)), pose(history.current()));
    }

    @Test
    void aRunBeforeItsFirstTickHasNothingToStepBackTo() {
        RunHistory history = new RunHistory(BuiltinRuns.live(MAP, 5, Set.of()));
        assertFalse(history.stepBack());
        history.step();
        assertTrue(history.stepBack());
        assertEquals(-1, history.current().tick());
    }

    @Test
    void aRunWhoseControllerCannotBeCopiedStepsOnlyForward() {
        RunHistory history = new RunHistory(new LiveRun(MAP, 5, Set.of(), BuiltinCar.FACTORY.unforked()));
        history.step();
        history.step();
        assertFalse(history.canStepBack());
        assertFalse(history.stepBack());
        assertEquals(1, history.current().tick());
    }
}
