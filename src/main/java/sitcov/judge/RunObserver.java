package sitcov.judge;

import sitcov.oracle.AccidentDetector;
import sitcov.vehicles.Scene;

/** Watches a run tick by tick (a trace writer, a renderer); it must not change the scene. */
@FunctionalInterface
public interface RunObserver {
    RunObserver NONE = (tick, scene, detector) -> { };

    /** Called after every tick, once all vehicles moved and the detector looked. */
    void afterTick(long tick, Scene scene, AccidentDetector detector);
}
