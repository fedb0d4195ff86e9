package sitcov.vehicles;

import java.util.Arrays;

/**
 * Who holds each junction: a four-way-stop lock shared by every vehicle. A vehicle asks before it
 * enters a junction square and lets go once its footprint has left it. A holder may always ask
 * again (no vehicle is blocked by its own lock); a lock held longer than the asker's patience is
 * taken over, so a stuck holder cannot block a junction for ever.
 */
public final class JunctionOccupancy {
    private static final int FREE = -1;

    private int[] holder;
    private long[] since;

    public JunctionOccupancy(int junctions) {
        holder = new int[junctions];
        since = new long[junctions];
        Arrays.fill(holder, FREE);
    }

    /**
     * Asks for junction {@code junction} on behalf of {@code vehicle} at {@code tick}.
     *
     * @param patience ticks after which another vehicle's lock is considered stale and taken over
     * @return true if {@code vehicle} now holds it
     */
    public boolean request(int junction, int vehicle, long tick, long patience) {
        int current = holder[junction];
        if (current == vehicle) {
            return true;
        }
        if (current == FREE || tick - since[junction] > patience) {
            holder[junction] = vehicle;
            since[junction] = tick;
            return true;
        }
        return false;
    }

    public void release(int junction, int vehicle) {
        if (junction >= 0 && holder[junction] == vehicle) {
            holder[junction] = FREE;
        }
    }

    /** Releases every junction {@code vehicle} holds (it left the map). */
    public void releaseAll(int vehicle) {
        for (int j = 0; j < holder.length; j++) {
            release(j, vehicle);
        }
    }

    public boolean isHeldBy(int junction, int vehicle) {
        return holder[junction] == vehicle;
    }

    /** The tick the junction's holder was given it. */
    public long since(int junction) {
        return since[junction];
    }

    /** The vehicle holding the junction, or -1. */
    public int holder(int junction) {
        return holder[junction];
    }
}
