package sitcov.judge;

import java.util.List;
import java.util.Set;
import sitcov.control.ControllerFactory;
import sitcov.engine.ModelCopy;
import sitcov.engine.SimState;
import sitcov.faults.Fault;
import sitcov.faults.FaultSwitchboard;
import sitcov.faults.SeededControllerFactory;
import sitcov.faults.Shadow;
import sitcov.geom.Box;
import sitcov.geom.CellIndex;
import sitcov.oracle.AccidentDetector;
import sitcov.oracle.Margins;
import sitcov.oracle.NearMisses;
import sitcov.oracle.RunResult;
import sitcov.vehicles.Scene;
import sitcov.vehicles.Telemetry;
import sitcov.world.Layout;
import sitcov.world.RoadNetwork;
import sitcov.world.WorldMap;

/**
 * One run that its owner steps a tick at a time: {@link Simulator} drives it to the end, a viewer
 * a tick per frame. The map, the internal seed and the faults fix it bit for bit.
 */
public final class LiveRun {
    /**
     * What a copy shares with its run, as nothing changes it once made: the map and its road network,
     * and the geometry's values. The records of values the map holds are shared without naming; any
     * other class is copied, and one a copy cannot write (a final field) is refused.
     */
    private static final ModelCopy.Sharing SHARED = new ModelCopy.Sharing(Set.of(
            WorldMap.class, Layout.class, RoadNetwork.class, Box.class, CellIndex.class));

    // not final, as in every class a checkpoint copies: a copy writes them (ModelCopy)
    private WorldMap map;
    private long internalSeed;
    private Set<Fault> faults;
    private SimState state;
    private FaultSwitchboard switchboard;
    private Scene scene;
    private AccidentDetector detector;
    private NearMisses nearMisses;
    private boolean copyable;
    private boolean ended;
    /** A replay of a run the experiment stopped at its verdict stops after as many ticks; else never. */
    private long stopAfter = Long.MAX_VALUE;

    /**
     * A run of the controller {@code controller} makes, with {@code faults} switched on: a controller
     * with seeded faults is handed the run's switchboard, any other knows no faults.
     */
    public LiveRun(WorldMap map, long internalSeed, Set<Fault> faults, ControllerFactory controller) {
        this(map, internalSeed, faults, Set.of(), controller);
    }

    private LiveRun(WorldMap map, long internalSeed, Set<Fault> faults, Set<Fault> watched, ControllerFactory controller) {
        this.map = map;
        this.internalSeed = internalSeed;
        this.faults = Set.copyOf(faults);
        this.state = new SimState(internalSeed);
        this.switchboard = watched.isEmpty() ? new FaultSwitchboard(faults, state)
                : FaultSwitchboard.shadowing(watched, state);
        this.scene = Scene.start(map, state, handing(switchboard, controller));
        this.detector = new AccidentDetector(scene.telemetry());
        state.schedule().scheduleRepeating(0, AccidentDetector.ORDERING, 1, detector);
        this.nearMisses = new NearMisses(scene.telemetry());
        this.copyable = controller.copyable();
    }

    /** The controllers of {@code controller}, each handed {@code board} when it knows seeded faults. */
    private static ControllerFactory handing(FaultSwitchboard board, ControllerFactory controller) {
        return controller instanceof SeededControllerFactory seeded ? run -> seeded.start(run, board) : controller;
    }

    /**
     * A checkpoint of this run: an independent run in this one's state (scene, controller, random
     * streams, schedule, detector, near-miss watcher) that steps on exactly as this one would. The
     * map is shared: nothing changes it. Only a run whose controller keeps all its state in the run
     * (the builtin car) can be copied; a controller in another process keeps state no copy can reach.
     *
     * @throws IllegalStateException if the run's controller cannot be copied
     */
    public LiveRun copy() {
        if (!copyable) {
            throw new IllegalStateException("a run of this controller cannot be copied: its state is not the run's");
        }
        return ModelCopy.of(this, SHARED);
    }

    /**
     * A recorded run again, for a viewer that steps it: the car driven by {@code commands} instead of a
     * controller, stopped after {@code stopAfter} ticks as the experiment stopped it ({@link Simulator#replay}).
     */
    public static LiveRun replaying(WorldMap map, long internalSeed, sitcov.vehicles.CommandLog commands, long stopAfter) {
        LiveRun run = new LiveRun(map, internalSeed, Set.of(), sitcov.vehicles.CommandPlayer.factory(commands));
        run.stopAfter = stopAfter;
        return run;
    }

    /** Keeps of each fault only whether and when it first acted, as a judged faulty run needs ({@link FaultSwitchboard#recordFirstEffectsOnly}). */
    LiveRun judged() {
        switchboard.recordFirstEffectsOnly();
        return this;
    }

    /** Whether {@link #copy} can copy this run (its controller keeps all its state in the run). */
    public boolean copyable() {
        return copyable;
    }

    /**
     * A fault-free run that watches {@code watched} from the shadows: it runs as any fault-free run
     * does, and tells when each watched fault would first have made a run differ ({@link #shadow}).
     */
    static LiveRun watching(WorldMap map, long internalSeed, Set<Fault> watched, ControllerFactory controller) {
        if (watched.isEmpty()) {
            throw new IllegalArgumentException("a run watching faults from the shadows needs faults to watch");
        }
        return new LiveRun(map, internalSeed, Set.of(), watched, controller);
    }

    /** What this run, {@link #watching} {@code fault}, saw of it so far. */
    Shadow shadow(Fault fault) {
        return switchboard.shadow(fault);
    }

    /**
     * A copy of this fault-free run with {@code fault} switched on from now: taken at the start of
     * the tick the fault departs, it goes on exactly as a run with the fault on from tick 0 would.
     */
    LiveRun forkWith(Fault fault, boolean reachedBefore) {
        LiveRun fork = copy();
        fork.switchboard.switchOn(fault, reachedBefore);
        fork.faults = Set.of(fault);
        return fork;
    }

    /** A copy of this fault-free run with every fault of {@code shadows} switched on from now, as {@link #forkWith}. */
    LiveRun forkWith(List<Shadow> shadows) {
        LiveRun fork = copy();
        long now = tick() + 1;
        for (Shadow s : shadows) {
            fork.switchboard.switchOn(s.fault(), s.reachedBefore(now));
        }
        fork.faults = shadows.stream().map(Shadow::fault).collect(java.util.stream.Collectors.toUnmodifiableSet());
        return fork;
    }

    /** How far {@link #advance} took the run. */
    public enum Progress {
        /** Its controller took the tick's observation and waits for its command: the tick is paused. */
        AWAITING_COMMAND,
        /** A tick ran to its end; more follow. */
        TICK_DONE,
        /** The run has ended (Target reached, timeout, or stopped). */
        ENDED
    }

    /**
     * Runs one tick, or up to where its controller waits for its command ({@link
     * sitcov.control.DeferredController}); the next call then finishes the paused tick.
     */
    public Progress advance() {
        boolean goesOn = state.step();
        if (goesOn && state.schedule().isPaused()) {
            return Progress.AWAITING_COMMAND;
        }
        if (goesOn) {
            // watched as a RunObserver watches, so the tick that ends the run is watched too
            nearMisses.afterTick(scene.telemetry());
            if (state.tick() + 1 >= stopAfter) {
                detector.stopAtVerdict(state);
            }
        }
        if (!goesOn && !ended) {
            ended = true;
            scene.autonomousCar().end(detector.outcome() == null ? "STOPPED" : detector.outcome().name(), detector.ticks());
        }
        return goesOn ? Progress.TICK_DONE : Progress.ENDED;
    }

    /**
     * Runs one tick whole; false once the run has ended (Target reached, timeout, or stopped). A
     * controller that answers later is answered at once, alone.
     */
    public boolean step() {
        Progress p = advance();
        while (p == Progress.AWAITING_COMMAND) {
            p = advance();
        }
        return p == Progress.TICK_DONE;
    }

    public long tick() {
        return state.tick();
    }

    /** The run as its watchers see it. */
    public Telemetry telemetry() {
        return scene.telemetry();
    }

    /** The live scene, for the viewer that steps and draws it. */
    public Scene scene() {
        return scene;
    }

    public AccidentDetector detector() {
        return detector;
    }

    /** How close the run has come to each accident so far. */
    public NearMisses nearMisses() {
        return nearMisses;
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
                detector.excusedContacts(), detector.ticks(), Margins.of(nearMisses),
                scene.telemetry().failure() == null ? "" : java.util.Objects.toString(scene.telemetry().failure().getMessage(), ""),
                scene.telemetry().clampedTicks());
        return new RunRecord(result, faults, switchboard.activations(), scene.autonomousCar().commandLog());
    }
}
