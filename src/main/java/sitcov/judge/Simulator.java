package sitcov.judge;

import java.util.Set;
import sitcov.control.ControllerFactory;
import sitcov.faults.Fault;
import sitcov.oracle.RunResult;
import sitcov.vehicles.CommandLog;
import sitcov.vehicles.CommandPlayer;
import sitcov.world.WorldMap;

/**
 * Runs one map with one internal seed and one set of faults, to the Target or the timeout. The
 * external seed (the map), the internal seed and the fault set fix the run bit for bit.
 */
public final class Simulator {
    private Simulator() {
    }

    /** A run of the controller {@code controller} makes, with {@code faults} switched on (for a controller with seeded faults). */
    public static RunRecord run(WorldMap map, long internalSeed, Set<Fault> faults, RunObserver observer,
                                ControllerFactory controller) {
        return run(map, internalSeed, faults, observer, null, controller);
    }

    /** A faulty run stopped once its verdict against {@code faultFree} (same map and seeds) is settled. */
    static RunRecord runUntilVerdict(WorldMap map, long internalSeed, Set<Fault> faults, RunResult faultFree,
                                     ControllerFactory controller) {
        return drive(new LiveRun(map, internalSeed, faults, controller).judged(), RunObserver.NONE,
                new VerdictWatch(faultFree));
    }

    /** A faulty run driven to its end, keeping of each fault only whether and when it first acted. */
    static RunRecord runJudged(WorldMap map, long internalSeed, Set<Fault> faults, ControllerFactory controller) {
        return drive(new LiveRun(map, internalSeed, faults, controller).judged(), RunObserver.NONE, null);
    }

    private static RunRecord run(WorldMap map, long internalSeed, Set<Fault> faults, RunObserver observer,
                                 VerdictWatch watch, ControllerFactory controller) {
        return drive(new LiveRun(map, internalSeed, faults, controller), observer, watch);
    }

    /**
     * A recorded run again: the car driven by the commands {@code commands} instead of a controller, on
     * the map and internal seed it was recorded on, stopped after {@code stopAfter} ticks where the
     * experiment stopped it at its verdict ({@code Long.MAX_VALUE}: run to its end). The world is
     * deterministic given the commands, so this is the recorded run, tick for tick, if nothing changed.
     */
    public static RunRecord replay(WorldMap map, long internalSeed, CommandLog commands, long stopAfter,
                                   RunObserver observer) {
        LiveRun run = new LiveRun(map, internalSeed, Set.of(), CommandPlayer.factory(commands));
        while (run.step()) {
            observer.afterTick(run.tick(), run.telemetry(), run.detector());
            if (run.tick() + 1 >= stopAfter) {
                run.detector().stopAtVerdict(run.state());
            }
        }
        return run.record();
    }

    /** Steps {@code run} to its end, or to its verdict against the run {@code watch} holds (when not null). */
    static RunRecord drive(LiveRun run, RunObserver observer, VerdictWatch watch) {
        while (run.step()) {
            observer.afterTick(run.tick(), run.telemetry(), run.detector());
            if (watch != null && watch.settled(run.detector(), run.tick())) {
                run.detector().stopAtVerdict(run.state());
            }
        }
        return run.record();
    }
}
