package sitcov.experiment;

import java.util.Set;
import sitcov.engine.SimState;
import sitcov.faults.Fault;
import sitcov.faults.FaultSwitchboard;
import sitcov.oracle.AccidentDetector;
import sitcov.oracle.RunResult;
import sitcov.vehicles.Scene;
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
        return run(map, internalSeed, faults, observer, null);
    }

    /** A faulty run stopped once its verdict against {@code faultFree} (same map and seeds) is settled. */
    static RunRecord runUntilVerdict(WorldMap map, long internalSeed, Set<Fault> faults, RunResult faultFree) {
        return run(map, internalSeed, faults, RunObserver.NONE, new VerdictWatch(faultFree));
    }

    private static RunRecord run(WorldMap map, long internalSeed, Set<Fault> faults, RunObserver observer,
                                 VerdictWatch watch) {
        SimState state = new SimState(internalSeed);
        FaultSwitchboard switchboard = new FaultSwitchboard(faults, state::tick);
        Scene scene = Scene.start(map, state, switchboard);
        AccidentDetector detector = new AccidentDetector(scene);
        state.schedule().scheduleRepeating(0, AccidentDetector.ORDERING, 1, detector);
        while (state.step()) {
            observer.afterTick(state.tick(), scene, detector);
            if (watch != null && watch.settled(detector)) {
                detector.stopAtVerdict(state);
            }
        }
        RunResult result = new RunResult(map.seed(), internalSeed, detector.outcome(), detector.accidents(),
                detector.excusedContacts(), detector.ticks());
        return new RunRecord(result, faults, switchboard.activations());
    }
}
