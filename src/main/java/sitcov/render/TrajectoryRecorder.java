package sitcov.render;

import java.util.Arrays;
import java.util.List;
import sitcov.control.Vehicle;
import sitcov.judge.RunObserver;
import sitcov.oracle.Accident;
import sitcov.oracle.AccidentDetector;
import sitcov.oracle.NearMisses;
import sitcov.vehicles.Telemetry;

/**
 * Records the autonomous car's path through one run, one entry per tick: where its front centre
 * was, where it faced, how fast it went, and whether its controller said it was overtaking or crossing a
 * junction. Entries are kept in growable primitive arrays, so a 5000-tick run costs a few hundred
 * kilobytes, not 5000 objects. Also keeps the detector's list of accidents, which is final once the
 * run is over, and watches the run's near misses ({@link NearMissWatch}) so that a picture can say
 * where each least value was reached.
 */
public final class TrajectoryRecorder implements RunObserver {
    private static final int INITIAL_CAPACITY = 256;

    private int ticks;
    private long[] tickNumbers = new long[INITIAL_CAPACITY];
    private double[] xs = new double[INITIAL_CAPACITY];
    private double[] ys = new double[INITIAL_CAPACITY];
    private double[] headings = new double[INITIAL_CAPACITY];
    private double[] speeds = new double[INITIAL_CAPACITY];
    private boolean[] overtaking = new boolean[INITIAL_CAPACITY];
    private boolean[] crossings = new boolean[INITIAL_CAPACITY];
    private List<Accident> accidents = List.of();
    private final NearMissWatch nearMisses = new NearMissWatch();

    @Override
    public void afterTick(long tick, Telemetry run, AccidentDetector detector) {
        if (ticks == xs.length) {
            grow();
        }
        Vehicle car = run.car();
        tickNumbers[ticks] = tick;
        xs[ticks] = car.x();
        ys[ticks] = car.y();
        headings[ticks] = car.heading();
        speeds[ticks] = car.speed();
        overtaking[ticks] = run.selfReport().overtaking();
        crossings[ticks] = run.selfReport().crossingJunction();
        ticks++;
        accidents = detector.accidents(); // a read-only view of the detector's list
        nearMisses.afterTick(tick, run, detector);
    }

    /** The run's near misses so far; empty before the first tick. */
    public java.util.Optional<NearMisses> nearMisses() {
        return nearMisses.started() ? java.util.Optional.of(nearMisses.nearMisses()) : java.util.Optional.empty();
    }

    /** The entry of the first tick at or after {@code tick}, or the last entry; −1 when none was recorded. */
    public int entryOf(long tick) {
        for (int i = 0; i < ticks; i++) {
            if (tickNumbers[i] >= tick) {
                return i;
            }
        }
        return ticks - 1;
    }

    private void grow() {
        int capacity = xs.length * 2;
        tickNumbers = Arrays.copyOf(tickNumbers, capacity);
        xs = Arrays.copyOf(xs, capacity);
        ys = Arrays.copyOf(ys, capacity);
        headings = Arrays.copyOf(headings, capacity);
        speeds = Arrays.copyOf(speeds, capacity);
        overtaking = Arrays.copyOf(overtaking, capacity);
        crossings = Arrays.copyOf(crossings, capacity);
    }

    /** How many ticks were recorded. */
    public int ticks() {
        return ticks;
    }

    /** The simulation tick of entry {@code i} (entry i is normally tick i). */
    public long tick(int i) {
        check(i);
        return tickNumbers[i];
    }

    /** The x of the car's front centre after entry {@code i}'s tick, in metres. */
    public double x(int i) {
        check(i);
        return xs[i];
    }

    public double y(int i) {
        check(i);
        return ys[i];
    }

    /** Bearing in degrees (0 south, 90 east, 180 north, 270 west). */
    public double heading(int i) {
        check(i);
        return headings[i];
    }

    /** Metres per tick. */
    public double speed(int i) {
        check(i);
        return speeds[i];
    }

    /** Whether the car's controller said it was overtaking (passing a parked car) in entry {@code i}'s tick. */
    public boolean overtaking(int i) {
        check(i);
        return overtaking[i];
    }

    /** Whether the car was turning through a junction square. */
    public boolean crossing(int i) {
        check(i);
        return crossings[i];
    }

    /** The accidents of the run, in order (all of them once the run is over). */
    public List<Accident> accidents() {
        return accidents;
    }

    private void check(int i) {
        if (i < 0 || i >= ticks) {
            throw new IndexOutOfBoundsException("entry " + i + " of a trajectory of " + ticks + " ticks");
        }
    }
}
