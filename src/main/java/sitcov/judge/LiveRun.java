package sitcov.judge;

import java.util.Set;
import sitcov.engine.SimState;
import sitcov.faults.Fault;
import sitcov.control.ControllerFactory;
import sitcov.faults.FaultSwitchboard;
import sitcov.vehicles.BuiltinCar;
import sitcov.oracle.AccidentDetector;
import sitcov.oracle.RunResult;
import sitcov.vehicles.Scene;
import sitcov.world.WorldMap;

/**
 * One run that its owner steps a tick at a time: {@link Simulator} drives it to the end, a viewer
 * a tick per frame. The map, the internal seed and the faults fix it bit for bit.
 */
public final class LiveRun {
    private final WorldMap map;
    private final long internalSeed;
    private final Set<Fault> faults;
    private final SimState state;
    private final FaultSwitchboard switchboard;
    private final Scene scene;
    private final AccidentDetector detector;
    private boolean ended;

    public LiveRun(WorldMap map, long internalSeed, Set<Fault> faults) {
        this(map, internalSeed, faults, BuiltinCar.factory());
    }

    /**
     * A run whose car is driven by the controller {@code controllers} makes; {@code faults} are
     * switched on in the run's switchboard, which the controller is handed.
     */
    public LiveRun(WorldMap map, long internalSeed, Set<Fault> faults, ControllerFactory controllers) {
        this.map = map;
        this.internalSeed = internalSeed;
        this.faults = Set.copyOf(faults);
        this.state = new SimState(internalSeed);
        this.switchboard = new FaultSwitchboard(faults, state::tick);
        this.scene = Scene.start(map, state, switchboard, controllers);
        this.detector = new AccidentDetector(scene);
        state.schedule().scheduleRepeating(0, AccidentDetector.ORDERING, 1, detector);
    }

    /** Runs one tick; false once the run has ended (Target reached, timeout, or stopped). */
    public boolean step() {
        boolean goesOn = state.step();
        if (!goesOn && !ended) {
            ended = true;
            scene.autonomousCar().end(detector.outcome() == null ? "STOPPED" : detector.outcome().name(), detector.ticks());
        }
        return goesOn;
    }

    public long tick() {
        return state.tick();
    }

    public Scene scene() {
        return scene;
    }

    public AccidentDetector detector() {
        return detector;
    }

    SimState state() {
        return state;
    }

    public WorldMap map() {
        return map;
    }

    public Set<Fault> faults() {
        return faults;
    }

    /** How the run went so far (all of it, once {@link #step} returned false). */
    public RunRecord record() {
        RunResult result = new RunResult(map.seed(), internalSeed, detector.outcome(), detector.accidents(),
                detector.excusedContacts(), detector.ticks());
        return new RunRecord(result, faults, switchboard.activations());
    }
}
