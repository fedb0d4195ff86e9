package sitcov.judge;

import sitcov.oracle.AccidentDetector;
import sitcov.vehicles.Telemetry;

/** Watches a run tick by tick (a trace writer, a renderer) through its telemetry, never the scene itself. */
@FunctionalInterface
public interface RunObserver {
    RunObserver NONE = (tick, run, detector) -> { };

    /** Called after every tick, once all vehicles moved and the detector looked. */
    void afterTick(long tick, Telemetry run, AccidentDetector detector);
}
