package sitcov.experiment;

import java.util.function.LongSupplier;

/**
 * One driver's wall time in a replication. While a resumed run replays the journal, its time is what
 * the journal recorded; after the last replayed map it runs on from there. A map another driver of
 * the replication judged is charged at the time it took that driver, as if this one had run it.
 */
final class DriverClock {
    private final LongSupplier now;
    private boolean live;
    private long replayedNanos;
    private long offset;
    private long liveSince;
    private long credited;
    private long liveMapNanos;
    private int liveMaps;

    /** A clock that starts now, or (when {@code replaying}) at the journal's times until {@link #replayed}'s last map. */
    DriverClock(LongSupplier now, boolean replaying) {
        this.now = now;
        this.live = !replaying;
        this.liveSince = now.getAsLong();
    }

    long now() {
        return now.getAsLong();
    }

    /** A map was replayed, the driver's time then being {@code driverNanos}; after the {@code last}, the clock runs. */
    void replayed(long driverNanos, boolean last) {
        replayedNanos = driverNanos;
        if (last) {
            offset = driverNanos;
            liveSince = now.getAsLong();
            live = true;
        }
    }

    /** A map was judged in {@code nanos} (as charged), of which {@code credit} were not spent by this driver. */
    void judged(long nanos, long credit) {
        credited += credit;
        liveMapNanos += nanos;
        liveMaps++;
    }

    /** The driver's wall time so far. */
    long elapsed() {
        return live ? offset + now.getAsLong() - liveSince + credited : replayedNanos;
    }

    /** What drawing one of {@code drawn} candidates has cost against judging a map (0 before a map was judged live). */
    double candidateCostInMaps(int drawn) {
        if (liveMaps == 0 || drawn == 0) {
            return 0;
        }
        double perMap = (double) liveMapNanos / liveMaps;
        double perCandidate = Math.max(0, elapsed() - liveMapNanos) / (double) drawn;
        return perCandidate / perMap;
    }
}
