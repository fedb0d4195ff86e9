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
 */
public final class FaultSwitchboard {
    private static final int N = Fault.values().length;

    private final Set<Fault> active;
    private final LongSupplier clock;
    private final boolean[] reached;
    private final long[] effectiveCount;
    private final long[] firstEffective;

    public FaultSwitchboard(Set<Fault> active, LongSupplier clock) {
        this.active = active.isEmpty() ? EnumSet.noneOf(Fault.class) : EnumSet.copyOf(active);
        this.clock = clock;
        this.reached = new boolean[N];
        this.effectiveCount = new long[N];
        this.firstEffective = new long[N];
        java.util.Arrays.fill(firstEffective, -1);
    }

    private FaultSwitchboard(Set<Fault> active, FaultSwitchboard sharing) {
        this.active = EnumSet.copyOf(active);
        this.clock = sharing.clock;
        this.reached = sharing.reached;
        this.effectiveCount = sharing.effectiveCount;
        this.firstEffective = sharing.firstEffective;
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

    public boolean isActive(Fault fault) {
        return active.contains(fault);
    }

    public Set<Fault> activeFaults() {
        return EnumSet.copyOf(active.isEmpty() ? EnumSet.noneOf(Fault.class) : active);
    }

    /** The faulty path of an active fault ran. */
    public void reached(Fault fault) {
        reached[fault.ordinal()] = true;
    }

    /** An active fault changed a value the car then used. */
    public void effective(Fault fault) {
        int i = fault.ordinal();
        reached[i] = true;
        if (effectiveCount[i]++ == 0) {
            firstEffective[i] = clock.getAsLong();
        }
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
