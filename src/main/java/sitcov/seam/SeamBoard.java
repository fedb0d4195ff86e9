package sitcov.seam;

import java.util.Arrays;

/**
 * The seam faults of one run, switched on or watched from the shadows, and what each did: whether it
 * was reached (its seam was consulted under its condition), how often it was effective (it changed a
 * value the controller received or the world applied) and first when. A fault watched from the
 * shadows changes nothing; the board records the first tick it would have been reached and the first
 * tick it would have changed a value ({@link SeamShadow#departureTick()}): until then a run with it
 * switched on is the watching run tick for tick.
 */
public final class SeamBoard {
    private static final int N = SeamFault.values().length;

    private boolean[] active = new boolean[N];
    private boolean[] shadowed = new boolean[N];
    private boolean[] reached = new boolean[N];
    private long[] effectiveCount = new long[N];
    private long[] firstEffective = filled();
    private long[] firstReached = filled();
    private long[] departed = filled();

    private static long[] filled() {
        long[] ticks = new long[N];
        Arrays.fill(ticks, -1);
        return ticks;
    }

    void switchOn(SeamFault fault) {
        active[fault.ordinal()] = true;
    }

    void watch(SeamFault fault) {
        shadowed[fault.ordinal()] = true;
    }

    boolean isActive(int fault) {
        return active[fault];
    }

    /** Whether the fault's distortion must run: it is on, or watched and not yet departed. */
    boolean watches(int fault) {
        return active[fault] || shadowed[fault] && departed[fault] < 0;
    }

    /** What the fault's seam saw in tick {@code tick}: reached there, and whether it changed a value. */
    void saw(int fault, long tick, boolean reachedNow, boolean changed) {
        boolean r = reachedNow || changed;
        if (shadowed[fault]) {
            if (r && firstReached[fault] < 0) {
                firstReached[fault] = tick;
            }
            if (changed && departed[fault] < 0) {
                departed[fault] = tick;
            }
            return;
        }
        reached[fault] |= r;
        if (changed && effectiveCount[fault]++ == 0) {
            firstEffective[fault] = tick;
        }
    }

    /**
     * Switches {@code fault} on in a run forked from a watching run at the start of the tick it departs,
     * and stops watching every other: {@code reachedBefore} carries over whether it was reached before.
     */
    public void forkWith(SeamFault fault, boolean reachedBefore) {
        if (!shadowed[fault.ordinal()]) {
            throw new IllegalStateException("seam fault " + fault.label() + " was not watched from the shadows");
        }
        Arrays.fill(shadowed, false);
        active[fault.ordinal()] = true;
        reached[fault.ordinal()] = reachedBefore;
    }

    /** What a watching board saw of {@code fault}. */
    public SeamShadow shadow(SeamFault fault) {
        int i = fault.ordinal();
        if (!shadowed[i]) {
            throw new IllegalArgumentException("seam fault " + fault.label() + " was not watched from the shadows");
        }
        return new SeamShadow(fault, firstReached[i], departed[i]);
    }

    /** What {@code fault}, switched on, did in the run. */
    public SeamActivation activation(SeamFault fault) {
        int i = fault.ordinal();
        return new SeamActivation(fault, reached[i], effectiveCount[i], firstEffective[i]);
    }
}
