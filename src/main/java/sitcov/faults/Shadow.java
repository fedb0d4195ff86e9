package sitcov.faults;

/**
 * What a fault-free run saw of a fault it watched without switching it on: the first tick its
 * faulty path would have run ({@code -1} if never) and the first tick its run would have differed
 * from the fault-free one ({@code -1} if never: the faulty run is then the fault-free run).
 */
public record Shadow(Fault fault, long firstReachedTick, long departureTick) {
    public boolean departs() {
        return departureTick >= 0;
    }

    /** Whether the faulty path ran in a tick before {@code tick}. */
    public boolean reachedBefore(long tick) {
        return firstReachedTick >= 0 && firstReachedTick < tick;
    }

    /** What the fault did in a run that never departed from the fault-free one. */
    public Activation activation() {
        return new Activation(fault, true, firstReachedTick >= 0, 0, -1);
    }
}
