package sitcov.experiment;

import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import sitcov.judge.JudgedMap;
import sitcov.world.WorldMap;

/**
 * What the drivers of one replication share: the maps judged so far, so a map two drivers run is
 * judged once and charged to both (the same map and seeds run the same), and the names of the
 * situations they built. A situation's name is its identity in runs.csv and names its file
 * ({@code situations/NAME.situation}), so each name is claimed once: a second driver (or the same
 * one again) running a situation under a name already run would get the first one's judged world and
 * overwrite its file, and is refused instead.
 */
final class SharedMaps {
    private final int replication;
    private final Map<MapId, Judged> judged = new ConcurrentHashMap<>();
    private final Map<String, String> situationNames = new ConcurrentHashMap<>();

    SharedMaps(int replication) {
        this.replication = replication;
    }

    /**
     * A map one driver of the replication judged, kept for the others, with the wall time it took and
     * the commands of its runs to record (the rest are let go of: a replication keeps every map it judged).
     */
    record Judged(WorldMap world, JudgedMap judged, long nanos, Map<Integer, sitcov.vehicles.CommandLog> recordings) {
    }

    /** The map judged under {@code id} in this replication, or null. */
    Judged judged(MapId id) {
        return judged.get(id);
    }

    void keep(MapId id, Judged map) {
        judged.putIfAbsent(id, map);
    }

    /**
     * Claims {@code name} for {@code driver}.
     *
     * @throws IllegalStateException naming both drivers when the name was run before in this replication
     */
    void claim(String name, String driver) {
        String first = situationNames.putIfAbsent(name, driver);
        if (first == null) {
            return;
        }
        String who = first.equals(driver) ? "it ran a situation of that name before"
                : "driver " + first + " ran a situation of that name before";
        throw new IllegalStateException("driver " + driver + " ran situation " + name + " in replication " + replication
                + ", but " + who + ": a situation's name names its file (situations/" + name + ".situation) and must"
                + " be unique in the experiment; name each built situation apart, by driver and replication (as"
                + " coverage-search does: search-r" + replication + "-N)");
    }
}
