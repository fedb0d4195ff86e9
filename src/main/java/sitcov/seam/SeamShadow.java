package sitcov.seam;

/**
 * What a run saw of a seam fault it watched without switching it on: the first tick it would have been
 * reached and the first tick it would have changed a value ({@code -1} if never: the faulty run is then
 * the watching run).
 */
public record SeamShadow(SeamFault fault, long firstReachedTick, long departureTick) {
    public boolean departs() {
        return departureTick >= 0;
    }

    public boolean reachedBefore(long tick) {
        return firstReachedTick >= 0 && firstReachedTick < tick;
    }

    public boolean reached() {
        return firstReachedTick >= 0;
    }
}
