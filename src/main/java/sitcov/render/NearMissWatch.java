package sitcov.render;

import sitcov.judge.RunObserver;
import sitcov.oracle.AccidentDetector;
import sitcov.oracle.NearMisses;
import sitcov.vehicles.Telemetry;

/**
 * A {@link NearMisses} watcher as a {@link RunObserver}, for whoever draws or prints a run and needs
 * more than {@code RunResult.margins()} keeps (the tick of each least value, the values as a trace
 * goes): it watches the same telemetry on the same ticks as the run's own watcher, so it sees the
 * same values. It is made at the first tick, as the observer first sees the run then.
 */
public final class NearMissWatch implements RunObserver {
    private NearMisses watcher;

    @Override
    public void afterTick(long tick, Telemetry run, AccidentDetector detector) {
        if (watcher == null) {
            watcher = new NearMisses(run);
        }
        watcher.afterTick(run);
    }

    /** The watcher, once a tick was watched. */
    public boolean started() {
        return watcher != null;
    }

    /** What was watched so far; fails before the first tick. */
    public NearMisses nearMisses() {
        if (watcher == null) {
            throw new IllegalStateException("no tick watched yet");
        }
        return watcher;
    }
}
