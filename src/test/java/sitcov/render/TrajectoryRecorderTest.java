package sitcov.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Set;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import sitcov.builtin.BuiltinRuns;
import sitcov.faults.Fault;
import sitcov.geom.Bearing;
import sitcov.judge.RunObserver;
import sitcov.judge.Simulator;
import sitcov.oracle.RunResult;
import sitcov.vehicles.Dynamics;
import sitcov.world.MapGenerator;
import sitcov.world.StartPose;
import sitcov.world.WorldMap;

class TrajectoryRecorderTest {

    private static final WorldMap MAP = MapGenerator.generate(3);
    private static final long INTERNAL_SEED = 100;

    private static TrajectoryRecorder recorder;
    private static RunResult result;

    @BeforeAll
    static void runOnce() {
        recorder = new TrajectoryRecorder();
        result = BuiltinRuns.run(MAP, INTERNAL_SEED, Set.of(), recorder).result();
    }

    @Test
    void holdsExactlyOneEntryForEachTickOfTheRun() {
        assertEquals(result.ticks(), recorder.ticks());
        for (int i = 0; i < recorder.ticks(); i++) {
            assertEquals(i, recorder.tick(i), "entry " + i);
        }
    }

    @Test
    void startsAtTheCarStartMovedByAtMostOneTickOfMotion() {
        StartPose start = MAP.layout().carStart().orElseThrow();
        double moved = Math.hypot(recorder.x(0) - start.position().x(), recorder.y(0) - start.position().y());
        assertTrue(moved <= Dynamics.MAX_SPEED + 1e-9, "the first entry is " + moved + " m from the start");
        assertTrue(Math.abs(Bearing.turn(start.heading().bearing(), recorder.heading(0))) <= Dynamics.MAX_TURN + 1e-9,
                "turned from " + start.heading().bearing() + " to " + recorder.heading(0) + " in one tick");
    }

    @Test
    void neverMovesFurtherInATickThanTheTopSpeedAndATurnAllow() {
        for (int i = 1; i < recorder.ticks(); i++) {
            double step = Math.hypot(recorder.x(i) - recorder.x(i - 1), recorder.y(i) - recorder.y(i - 1));
            assertTrue(step <= Dynamics.MAX_SPEED + 0.5, "moved " + step + " m at tick " + i);
            assertTrue(Math.abs(recorder.speed(i)) <= Dynamics.MAX_SPEED + 1e-9, "speed at " + i);
        }
    }

    @Test
    void keepsTheRunsFinalListOfAccidents() {
        // waypoints displaced south-east take the car off the road on nearly every map
        TrajectoryRecorder faulty = new TrajectoryRecorder();
        RunResult run = BuiltinRuns.run(MAP, INTERNAL_SEED, Set.of(Fault.WAYPOINTS_SOUTH_EAST), faulty).result();
        assertTrue(run.hasAccident(), "the fixture needs a run with accidents, got " + run.accidents());
        assertEquals(run.accidents(), faulty.accidents());
    }

    @Test
    void recordsTheCarsStateInEveryEntry() {
        for (int i = 0; i < recorder.ticks(); i++) {
            if (recorder.crossing(i)) {
                assertFalse(recorder.overtaking(i), "overtakes while crossing at " + i);
            }
        }
    }

    @Test
    void refusesAnEntryItDoesNotHave() {
        assertThrows(IndexOutOfBoundsException.class, () -> recorder.x(recorder.ticks()));
        assertThrows(IndexOutOfBoundsException.class, () -> recorder.overtaking(-1));
        TrajectoryRecorder empty = new TrajectoryRecorder();
        assertEquals(0, empty.ticks());
        assertEquals(0, empty.accidents().size());
        assertThrows(IndexOutOfBoundsException.class, () -> empty.y(0));
    }

    @Test
    void twoObserversWatchingAtOnceLeaveTheRunAsAnUnobservedRunWouldBe() {
        TrajectoryRecorder first = new TrajectoryRecorder();
        TrajectoryRecorder second = new TrajectoryRecorder();
        RunObserver both = (tick, scene, detector) -> {
            first.afterTick(tick, scene, detector);
            second.afterTick(tick, scene, detector);
        };
        RunResult observed = BuiltinRuns.run(MAP, INTERNAL_SEED, Set.of(), both).result();
        assertEquals(BuiltinRuns.run(MAP, INTERNAL_SEED), observed);
        assertEquals(first.ticks(), second.ticks());
        assertEquals(recorder.x(recorder.ticks() - 1), second.x(second.ticks() - 1));
    }
}
