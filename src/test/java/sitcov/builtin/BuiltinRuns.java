package sitcov.builtin;

import java.util.List;
import java.util.Set;
import sitcov.engine.SimState;
import sitcov.faults.Fault;
import sitcov.faults.FaultSwitchboard;
import sitcov.judge.FaultyRuns;
import sitcov.judge.JudgedMap;
import sitcov.judge.LiveRun;
import sitcov.judge.MapRunner;
import sitcov.judge.RunObserver;
import sitcov.judge.RunRecord;
import sitcov.judge.Simulator;
import sitcov.oracle.RunResult;
import sitcov.vehicles.Scene;
import sitcov.world.WorldMap;

/** Runs of the builtin car, for tests: the main code names the controller every time, tests mostly mean this one. */
public final class BuiltinRuns {
    private BuiltinRuns() {
    }

    /** A fault-free run of the builtin car. */
    public static RunResult run(WorldMap map, long internalSeed) {
        return run(map, internalSeed, Set.of(), RunObserver.NONE).result();
    }

    public static RunRecord run(WorldMap map, long internalSeed, Set<Fault> faults, RunObserver observer) {
        return Simulator.run(map, internalSeed, faults, observer, BuiltinCar.FACTORY);
    }

    /** A live run of the builtin car with {@code faults} switched on. */
    public static LiveRun live(WorldMap map, long internalSeed, Set<Fault> faults) {
        return new LiveRun(map, internalSeed, faults, BuiltinCar.FACTORY);
    }

    /** Every fault of {@code faults} judged on the builtin car, each faulty run driven to its end. */
    public static JudgedMap judge(WorldMap map, long internalSeed, List<Fault> faults) {
        return judge(map, internalSeed, faults, FaultyRuns.TO_END);
    }

    public static JudgedMap judge(WorldMap map, long internalSeed, List<Fault> faults, FaultyRuns length) {
        return MapRunner.judge(map, internalSeed, faults, length, BuiltinCar.FACTORY);
    }

    /** A scene driven by the builtin car acting on {@code faults} (which records what they do). */
    public static Scene scene(WorldMap map, SimState state, FaultSwitchboard faults) {
        return Scene.start(map, state, run -> BuiltinCar.FACTORY.start(run, faults));
    }
}
