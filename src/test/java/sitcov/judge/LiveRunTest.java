package sitcov.judge;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.EnumSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.function.Supplier;
import org.junit.jupiter.api.Test;
import sitcov.builtin.BuiltinCar;
import sitcov.builtin.BuiltinRuns;
import sitcov.control.SelfReport;
import sitcov.control.Vehicle;
import sitcov.faults.Fault;
import sitcov.faults.Shadow;
import sitcov.world.MapGenerator;
import sitcov.world.WorldMap;

class LiveRunTest {
    /**
     * A map whose fault-free run, short as it is, waits behind a parked car, pulls out, passes and
     * pulls in, and waits at and crosses junctions: copies taken there reach every object such a car
     * holds. Every kind of run is copied on it; the fault-free, watching and forked runs on a second.
     */
    private static final long EVERY_KIND_MAP = 40;
    private static final long SECOND_MAP = 10;
    /** Ticks between the copies taken to see that one can be taken, besides one as the run first comes to each state. */
    private static final int COPY_EVERY = 20;
    /** The tick a run is followed to: past the fault-free runs' ends, short of the faulty runs' timeouts. */
    private static final long FOLLOWED_TO = 260;

    private static RunRecord toEnd(LiveRun run) {
        while (run.step()) {
            // stepped to the end
        }
        return run.record();
    }

    @Test
    void aCopyTakenMidRunEndsAsTheRunItselfAndAsAFreshRunDo() {
        int withAccidents = 0;
        for (long seed = 1; seed <= 6; seed++) {
            WorldMap map = MapGenerator.generate(seed);
            Set<Fault> faults = seed % 2 == 0 ? Set.of() : Set.of(Fault.ofId((int) seed % 20));
            RunRecord fresh = toEnd(BuiltinRuns.live(map, seed * 7, faults));
            LiveRun run = BuiltinRuns.live(map, seed * 7, faults);
            for (long t = 0; t < fresh.result().ticks() / 2; t++) {
                run.step();
            }
            LiveRun copy = run.copy();
            assertNotSame(run.scene(), copy.scene());
            RunRecord fromCopy = toEnd(copy);
            RunRecord fromOriginal = toEnd(run);
            String seeds = "map " + seed + " internal seed " + seed * 7 + " faults " + faults;
            assertEquals(fresh, fromCopy, seeds);
            assertEquals(fresh, fromOriginal, seeds);
            withAccidents += fresh.result().hasAccident() ? 1 : 0;
        }
        assertTrue(withAccidents > 0, "some of the runs copied have accidents");
    }

    /**
     * Every kind of run the project copies, copied all through: a field a copy cannot write (a final
     * one) or an object it cannot copy fails here rather than in a user's run.
     */
    @Test
    void everyKindOfRunCanBeCopiedInEveryStateItPassesAndEachCopyEndsAsTheRunDoes() {
        Set<String> states = new TreeSet<>();
        for (long seed : new long[] {EVERY_KIND_MAP, SECOND_MAP}) {
            WorldMap map = MapGenerator.generate(seed);
            List<Fault> each = seed == EVERY_KIND_MAP ? List.of(Fault.values()) : List.of();
            for (Map.Entry<String, Supplier<LiveRun>> kind : kinds(map, seed, each).entrySet()) {
                states.addAll(copiedThroughout(kind.getValue().get(), "map " + seed + ", " + kind.getKey()));
            }
        }
        for (String state : List.of("WAITING", "START", "PULLED_OUT", "FINISH", "at a junction", "crossing", "accident")) {
            assertTrue(states.stream().anyMatch(s -> s.contains(state)), "no copy was taken " + state + ": " + states);
        }
    }

    /** The runs a checkpoint is taken of: fault-free, with each of {@code each} on, watching every fault, and forks of each kind. */
    private static Map<String, Supplier<LiveRun>> kinds(WorldMap map, long seed, List<Fault> each) {
        Map<String, Supplier<LiveRun>> kinds = new LinkedHashMap<>();
        kinds.put("fault-free", () -> BuiltinRuns.live(map, seed, Set.of()));
        for (Fault f : each) {
            kinds.put("fault " + f.id(), () -> BuiltinRuns.live(map, seed, Set.of(f)));
        }
        kinds.put("watching every fault", () -> LiveRun.watching(map, seed, EnumSet.allOf(Fault.class), BuiltinCar.FACTORY));
        // forks as ForkedRuns makes them, at a tick the car is still driving up to its first manoeuvre
        kinds.put("forked with fault 17, judged", () -> after(40, BuiltinRuns.live(map, seed, Set.of()))
                .forkWith(Fault.ofId(17), false).judged());
        kinds.put("forked with faults 7 and 14, a version", () -> after(40, BuiltinRuns.live(map, seed, Set.of()))
                .forkWith(List.of(new Shadow(Fault.ofId(7), 3, 41), new Shadow(Fault.ofId(14), -1, 41))));
        return kinds;
    }

    private static LiveRun after(long ticks, LiveRun run) {
        while (run.tick() < ticks - 1) {
            run.step();
        }
        return run;
    }

    /**
     * Steps {@code run} to its end or to {@link #FOLLOWED_TO}, copying it as it first comes to each
     * state and every {@link #COPY_EVERY} ticks. The copies taken as it first passes a parked car, first
     * comes to a junction and first has had an accident, and one taken where it stopped, must go on
     * as it did.
     *
     * @return the states it was copied in
     */
    private static Set<String> copiedThroughout(LiveRun run, String label) {
        Set<String> states = new TreeSet<>();
        Map<String, LiveRun> followed = new LinkedHashMap<>();
        boolean goesOn = true;
        while (goesOn && run.tick() < FOLLOWED_TO) {
            goesOn = run.step();
            String state = state(run);
            if (states.add(state) || run.tick() % COPY_EVERY == 0) {
                LiveRun copy = run.copy();
                for (String followedState : List.of("PULLED_OUT", "junction", "accident")) {
                    if (state.contains(followedState)) {
                        followed.putIfAbsent(followedState, copy);
                    }
                }
            }
        }
        long stopped = run.tick();
        List<Object> end = ending(run);
        for (Map.Entry<String, LiveRun> copy : followed.entrySet()) {
            LiveRun c = copy.getValue();
            while (c.tick() < stopped && c.step()) {
                // stepped to where the run stopped
            }
            // a run that ended found so in one step more, which its copy must take too
            boolean copyGoesOn = c.tick() == stopped && (goesOn || c.step());
            assertEquals(goesOn, copyGoesOn, label + ", copied " + copy.getKey() + ": ends where the run did");
            assertEquals(end, ending(c), label + ", copied " + copy.getKey());
        }
        LiveRun last = run.copy();
        boolean lastGoesOn = last.step();
        assertEquals(run.step(), lastGoesOn, label + ": a copy taken where the run stopped steps on as it does");
        assertEquals(ending(run), ending(last), label + ", copied where it stopped");
        return states;
    }

    /** Where the car is in its manoeuvres, by its own account, and whether the run has had an accident. */
    private static String state(LiveRun run) {
        SelfReport report = run.telemetry().selfReport();
        return "overtaking " + report.stage() + (report.waitingAtJunction() ? ", waiting at a junction" : "")
                + (report.crossingJunction() ? ", crossing a junction" : "")
                + (run.detector().accidents().isEmpty() ? "" : ", after an accident");
    }

    /** How the run went, where each car is, and for a run watching faults, what it saw of each. */
    private static List<Object> ending(LiveRun run) {
        List<Object> ending = new ArrayList<>(List.of(run.tick(), run.record()));
        List<Vehicle> cars = new ArrayList<>(List.of(run.telemetry().car()));
        cars.addAll(run.telemetry().movingCars());
        for (Vehicle v : cars) {
            ending.add(List.of(v.id(), v.x(), v.y(), v.heading(), v.speed()));
        }
        if (run.faults().isEmpty()) {
            for (Fault f : Fault.values()) {
                try {
                    ending.add(run.shadow(f));
                } catch (IllegalArgumentException notWatched) {
                    break; // a fault-free run that watches no fault
                }
            }
        }
        return ending;
    }
}
