package sitcov.analysis;

import java.util.Arrays;
import java.util.List;
import sitcov.experiment.DriverRun;
import sitcov.experiment.MapRun;
import sitcov.judge.Variant;
import sitcov.judge.Notion;

/**
 * Faults found against compute spent, for one driver in one replication, under the differential
 * oracle: for each fault, the simulated ticks and the candidates the driver had spent when a map
 * first found it (counting that map whole), and the curve of distinct faults found against ticks.
 * Ticks are what the ticks budget charges (every run of a map), so drivers compare for equal compute.
 */
public final class Discovery {
    /** Marks a fault never found. */
    public static final long NEVER = -1;

    private final List<Variant> faults;
    private final long[] ticksAtFirst;
    private final int[] candidatesAtFirst;
    private final long ticksSpent;

    private Discovery(List<Variant> faults, long[] ticksAtFirst, int[] candidatesAtFirst, long ticksSpent) {
        this.faults = faults;
        this.ticksAtFirst = ticksAtFirst;
        this.candidatesAtFirst = candidatesAtFirst;
        this.ticksSpent = ticksSpent;
    }

    public static Discovery of(DriverRun run, List<Variant> faults) {
        long[] ticksAt = new long[faults.size()];
        int[] candidatesAt = new int[faults.size()];
        Arrays.fill(ticksAt, NEVER);
        Arrays.fill(candidatesAt, (int) NEVER);
        long ticks = 0;
        for (MapRun map : run.maps()) {
            ticks += map.ticks();
            for (int f = 0; f < faults.size(); f++) {
                if (ticksAt[f] == NEVER && map.faults().get(f).found(Notion.DIFFERENTIAL)) {
                    ticksAt[f] = ticks;
                    // a built situation (candidate -1) costs no candidate: count the ones drawn so far
                    candidatesAt[f] = Math.max(0, map.candidate() + 1);
                }
            }
        }
        return new Discovery(List.copyOf(faults), ticksAt, candidatesAt, run.spend().ticks());
    }

    public List<Variant> faults() {
        return faults;
    }

    /** Ticks spent when fault {@code f} (index in the fault list) was first found, or {@link #NEVER}. */
    public long ticksAtFirst(int f) {
        return ticksAtFirst[f];
    }

    /** Candidates drawn when fault {@code f} was first found, or {@link #NEVER}. */
    public int candidatesAtFirst(int f) {
        return candidatesAtFirst[f];
    }

    public long ticksSpent() {
        return ticksSpent;
    }

    /** Distinct faults found with at most {@code ticks} spent. */
    public int foundBy(long ticks) {
        int n = 0;
        for (long t : ticksAtFirst) {
            n += t != NEVER && t <= ticks ? 1 : 0;
        }
        return n;
    }

    /**
     * The area under the curve of distinct faults found against ticks from 0 to {@code horizon},
     * as a share of the whole rectangle (every fault found from the first tick): 1 is best. Drivers
     * of a replication are compared over one horizon, the least any of them spent.
     */
    public double area(long horizon) {
        if (horizon <= 0 || faults.isEmpty()) {
            return 0;
        }
        double area = 0;
        for (long t : ticksAtFirst) {
            if (t != NEVER && t <= horizon) {
                area += horizon - t;
            }
        }
        return area / ((double) horizon * faults.size());
    }
}
