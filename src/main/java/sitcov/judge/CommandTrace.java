package sitcov.judge;

import java.util.Arrays;
import sitcov.oracle.AccidentDetector;
import sitcov.vehicles.Telemetry;

/**
 * The commands the world carried out in a reference run, tick by tick, so that a run of another
 * controller on the same map and seeds can tell where it first acted differently: the tick its
 * command (after clamping) first differs is where the variant first had an effect.
 */
final class CommandTrace implements RunObserver {
    private double[] speedChange = new double[512];
    private double[] steering = new double[512];
    private int ticks;

    @Override
    public void afterTick(long tick, Telemetry run, AccidentDetector detector) {
        if (ticks == speedChange.length) {
            speedChange = Arrays.copyOf(speedChange, 2 * ticks);
            steering = Arrays.copyOf(steering, 2 * ticks);
        }
        speedChange[ticks] = run.speedChange();
        steering[ticks] = run.steering();
        ticks++;
    }

    /** A watcher of another run that compares its commands with these. */
    Comparison comparison() {
        return new Comparison();
    }

    /** Where a run's commands differ from the reference's; a tick past the reference's end differs. */
    final class Comparison implements RunObserver {
        private int tick;
        private long differing;
        private long first = -1;

        @Override
        public void afterTick(long t, Telemetry run, AccidentDetector detector) {
            boolean same = tick < ticks
                    && Double.compare(speedChange[tick], run.speedChange()) == 0
                    && Double.compare(steering[tick], run.steering()) == 0;
            if (!same) {
                differing++;
                if (first < 0) {
                    first = tick;
                }
            }
            tick++;
        }

        long differing() {
            return differing;
        }

        /** The first tick that differed, or -1. */
        long first() {
            return first;
        }
    }
}
