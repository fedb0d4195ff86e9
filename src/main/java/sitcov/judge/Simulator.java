package sitcov.judge;

import java.util.Set;
import sitcov.control.ControllerFactory;
import sitcov.faults.Fault;
import sitcov.oracle.RunResult;
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
