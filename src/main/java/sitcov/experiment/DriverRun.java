package sitcov.experiment;

import java.util.List;

/** One driver's share of one replication: the maps it ran, in order, and what it spent. */
public record DriverRun(String driver, List<MapRun> maps, DriverSpend spend) {
    public DriverRun {
        maps = List.copyOf(maps);
    }
}
