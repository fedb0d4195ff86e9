package sitcov.faults;

import java.util.ArrayList;
import java.util.EnumSet;
import java.util.List;
import java.util.Set;
import java.util.function.LongSupplier;

/**
 * The faults switched on for one run, consulted by the car at each seeded fault's seam, and the
 * record of what each did. Seams call {@link #reached} when the faulty path runs and
 * {@link #effective} when it changed a value the car then used. With no fault active nothing is
 * recorded and nothing changes, so a fault-free run is the same with or without the machinery.
 *
 * <p>A <em>shadowing</em> board serves a fault-free run that watches faults it does not switch on:
 * each watched fault's seam works out its faulty value beside the fault-free one, uses the
 * fault-free one, and tells the board when the two would first differ ({@link #departs}). Until that
 * tick a run with the fault on is the fault-free run tick for tick, so it can be forked from a
 * checkpoint of the fault-free run there; a fault that never departs is judged without a run.
 */
public final class FaultSwitchboard {
    private static final int N = Fault.values().length;

    private EnumSet<Fault> active;
    private LongSupplier clock;
    private boolean[] reached;
    private long[] effectiveCount;
    private long[] firstEffective;
    private EnumSet<Fault> shadowed;
    private long[] shadowReached;
    private long[] departed;
    private boolean firstEffectsOnly;

    public FaultSwitchboard(Set<Fault> active, LongSupplier clock) {
        this(active, Set.of(), clock);
    }

    private FaultSwitchboard(Set<Fault> active, Set<Fault> shadowed, LongSupplier clock) {
        this.active = active.isEmpty() ? EnumSet.noneOf(Fault.class) : EnumSet.copyOf(active);
        this.clock = clock;
        this.reached = new boolean[N];
        this.effectiveCount = new long[N];
        this.firstEffective = new long[N];
        java.util.Arrays.fill(firstEffective, -1);
        this.shadowed = shadowed.isEmpty() ? EnumSet.noneOf(Fault.class) : EnumSet.copyOf(shadowed);
        this.shadowReached = new long[N];
        this.departed = new long[N];
        java.util.Arrays.fill(shadowReached, -1);
        java.util.Arrays.fill(departed, -1);
    }

    private FaultSwitchboard(Set<Fault> active, FaultSwitchboard sharing) {
        this.active = EnumSet.copyOf(active);
        this.clock = sharing.clock;
        this.reached = sharing.reached;
        this.effectiveCount = sharing.effectiveCount;
        this.firstEffective = sharing.firstEffective;
        this.shadowed = sharing.shadowed;
        this.shadowReached = sharing.shadowReached;
        this.departed = sharing.departed;
    }

    /**
     * Tells the seams that only whether and when each fault first acted will be read (a judged run's
     * verdict and row need no more): a seam whose record costs work of its own, the degraded camera's
     * second look, may then skip it once its fault has acted. What the car does is the same.
     */
    public void recordFirstEffectsOnly() {
        firstEffectsOnly = true;
    }

    /** Whether nothing more about {@code fault} needs recording: it acted, and only first effects are kept. */
    public boolean recorded(Fault fault) {
        return firstEffectsOnly && effectiveCount[fault.ordinal()] > 0;
    }

    /** A board for a fault-free run that watches {@code watched} from the shadows: none of them acts. */
    public static FaultSwitchboard shadowing(Set<Fault> watched, LongSupplier clock) {
        return new FaultSwitchboard(Set.of(), watched, clock);
    }

    /**
     * A board with {@code more} switched on as well that records into this one: a controller with
     * faults planted in it acts on them, and what the run's own faults did is still this board's record.
     */
    public FaultSwitchboard alsoWith(Set<Fault> more) {
        EnumSet<Fault> all = EnumSet.noneOf(Fault.class);
        all.addAll(active);
        all.addAll(more);
        return new FaultSwitchboard(all, this);
    }

    /** A switchboard with every fault off. */
    public static FaultSwitchboard none() {
        return new FaultSwitchboard(Set.of(), () -> 0);
    }

    /** Whether the fault's faulty values are used. */
    public boolean isActive(Fault fault) {
        return active.contains(fault);
    }

    /**
     * Whether the fault's seam must work out its faulty value: the fault is on, or a fault-free run
     * watches it and it has not yet departed (after that, nothing more is asked of its shadow).
     */
    public boolean watches(Fault fault) {
        return active.contains(fault) || shadowed.contains(fault) && departed[fault.ordinal()] < 0;
    }

    public Set<Fault> activeFaults() {
        return EnumSet.copyOf(active.isEmpty() ? EnumSet.noneOf(Fault.class) : active);
    }

    /** The faulty path of a watched fault ran. */
    public void reached(Fault fault) {
        int i = fault.ordinal();
        if (shadowed.contains(fault)) {
            if (shadowReached[i] < 0) {
                shadowReached[i] = clock.getAsLong();
            }
            return;
        }
        reached[i] = true;
    }

    /** A watched fault changed a value the car then used (in the shadows: would have; so it departs). */
    public void effective(Fault fault) {
        int i = fault.ordinal();
        if (shadowed.contains(fault)) {
            reached(fault);
            departs(fault);
            return;
        }
        reached[i] = true;
        if (effectiveCount[i]++ == 0) {
            firstEffective[i] = clock.getAsLong();
        }
    }

    /**
     * A watched fault's faulty path left state or a value different from the fault-free run's, even
     * if not yet one the car used (a waypoint registered under a reused identity, a steering bearing
     * off by less than counts as effective). Only a shadowing board records it; a run with the fault on
     * has departed by then anyway.
     */
    public void departs(Fault fault) {
        int i = fault.ordinal();
        if (shadowed.contains(fault) && departed[i] < 0) {
            departed[i] = clock.getAsLong();
        }
    }

    /** What a shadowing board saw of {@code fault}: when it would first have been reached and first departed. */
    public Shadow shadow(Fault fault) {
        if (!shadowed.contains(fault)) {
            throw new IllegalArgumentException("fault " + fault.id() + " was not watched from the shadows");
        }
        return new Shadow(fault, shadowReached[fault.ordinal()], departed[fault.ordinal()]);
    }

    /**
     * Switches {@code fault} on in a run forked from a checkpoint of the fault-free run at the start
     * of the tick its fault departs; {@code reachedBefore} carries over whether its faulty path had
     * already run in the ticks before.
     */
    public void switchOn(Fault fault, boolean reachedBefore) {
        if (!shadowed.isEmpty()) {
            throw new IllegalStateException("a board watching faults from the shadows cannot have one switched on");
        }
        active.add(fault);
        reached[fault.ordinal()] = reachedBefore;
    }

    public Activation activation(Fault fault) {
        int i = fault.ordinal();
        return new Activation(fault, isActive(fault), reached[i], effectiveCount[i], firstEffective[i]);
    }

    /** The activation of every fault, in id order. */
    public List<Activation> activations() {
        List<Activation> all = new ArrayList<>(N);
        for (Fault f : Fault.values()) {
            all.add(activation(f));
        }
        return all;
    }
}
