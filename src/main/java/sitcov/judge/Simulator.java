package sitcov.judge;

import java.util.Set;
import sitcov.control.ControllerFactory;
import sitcov.faults.Fault;
import sitcov.oracle.RunResult;
import sitcov.vehicles.BuiltinCar;
import sitcov.world.WorldMap;

/**
 * Runs one map with one internal seed and one set of faults, to the Target or the timeout. The
 * external seed (the map), the internal seed and the fault set fix the run bit for bit.
 */
public final class Simulator {
    private Simulator() {
    }

    /** A fault-free run. */
    public static RunResult run(WorldMap map, long internalSeed) {
        return run(map, internalSeed, Set.of(), RunObserver.NONE).result();
    }

    public static RunRecord run(WorldMap map, long internalSeed, Set<Fault> faults, RunObserver observer) {
        return run(map, internalSeed, faults, BuiltinCar.factory(), observer, null);
    }

    /** A run whose car is driven by the controller {@code controllers} makes, with {@code faults} switched on. */
    public static RunRecord run(WorldMap map, long internalSeed, Set<Fault> faults, ControllerFactory controllers,
                                RunObserver observer) {
        return run(map, internalSeed, faults, controllers, observer, null);
    }

    /** A faulty run stopped once its verdict against {@code faultFree} (same map and seeds) is settled. */
    static RunRecord runUntilVerdict(WorldMap map, long internalSeed, Set<Fault> faults, RunResult faultFree) {
        return run(map, internalSeed, faults, BuiltinCar.factory(), RunObserver.NONE, new VerdictWatch(faultFree));
    }

    private static RunRecord run(WorldMap map, long internalSeed, Set<Fault> faults, ControllerFactory controllers,
                                 RunObserver observer, VerdictWatch watch) {
        LiveRun run = new LiveRun(map, internalSeed, faults, controllers);
        while (run.step()) {
            observer.afterTick(run.tick(), run.scene(), run.detector());
            if (watch != null && watch.settled(run.detector())) {
                run.detector().stopAtVerdict(run.state());
            }
        }
        return run.record();
    }
}
