package sitcov.experiment;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;

/**
 * What a results folder already holds of an experiment: the maps each driver judged in each
 * replication, in order, with the wall time they took, and the drivers that finished. A resumed
 * run replays it instead of simulating again, so it ends exactly where an uninterrupted run would.
 */
public final class Journal {
    /** A judged map, how long it took and the driver's elapsed time when it was done. */
    public record Entry(MapRun run, long mapNanos, long driverNanos) {
    }

    /** A driver that finished its share of a replication, and its total wall time. */
    public record Finished(DriverSpend spend, long driverNanos) {
        /** Why the replayed driver stops after drawing {@code drawn} candidates: where it stopped before, or null. */
        StopReason stopAt(int drawn) {
            return drawn < spend.candidates() ? null : spend.stoppedBy();
        }

        /** This, after checking that the driver replayed to the same spend. */
        Finished replayedTo(DriverSpend replayed) {
            if (!spend.equals(replayed)) {
                throw new IllegalStateException("the journal does not match this run: driver " + spend.driver()
                        + " in replication " + spend.replication() + " finished with " + spend + " but replays to "
                        + replayed);
            }
            return this;
        }
    }

    private final Map<DriverKey, List<Entry>> maps = new HashMap<>();
    private final Map<DriverKey, Finished> finished = new HashMap<>();
    private int size;

    public static Journal empty() {
        return new Journal();
    }

    /** Adds the next map of its driver and replication; maps must arrive in order. */
    public void add(Entry entry) {
        MapRun run = entry.run();
        List<Entry> list = maps.computeIfAbsent(DriverKey.of(run), k -> new ArrayList<>());
        if (run.mapIndex() != list.size()) {
            throw new IllegalArgumentException("map " + run.mapIndex() + " of driver " + run.driver() + " in replication "
                    + run.replication() + " follows " + list.size() + " maps; the journal has a gap");
        }
        list.add(entry);
        size++;
    }

    public void add(Finished f) {
        if (finished.putIfAbsent(DriverKey.of(f.spend()), f) != null) {
            throw new IllegalArgumentException("driver " + f.spend().driver() + " finished replication "
                    + f.spend().replication() + " twice");
        }
    }

    public List<Entry> maps(int replication, String driver) {
        return maps.getOrDefault(new DriverKey(replication, driver), List.of());
    }

    public Optional<Finished> finished(int replication, String driver) {
        return Optional.ofNullable(finished.get(new DriverKey(replication, driver)));
    }

    /** Every journaled map, in no particular order. */
    public List<Entry> entries() {
        List<Entry> all = new ArrayList<>(size);
        maps.values().forEach(all::addAll);
        return all;
    }

    /** Every finished driver, in no particular order. */
    public List<Finished> finished() {
        return new ArrayList<>(finished.values());
    }

    /** Maps judged in all. */
    public int size() {
        return size;
    }

    public int finishedCount() {
        return finished.size();
    }
}
