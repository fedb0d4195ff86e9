package sitcov.results;

import java.util.HashMap;
import java.util.List;
import java.util.Map;
import sitcov.experiment.DriverKey;

/**
 * {@code timings.csv}: the wall time of every judged map ({@code map} rows: the map's nanoseconds
 * and the driver's elapsed nanoseconds when it was done) and of every driver ({@code done} rows,
 * whose {@code map_index} is the number of maps it ran). A resumed wall-clock budget continues from these.
 */
public final class TimingsCsv {
    public static final Columns COLUMNS =
            Columns.of("replication", "driver", "event", "map_index", "map_nanos", "driver_nanos");
    public static final String HEADER = COLUMNS.header();
    private static final String MAP = "map";
    private static final String DONE = "done";

    /** The wall times read from a timings file: each map's (map and driver nanoseconds), each driver's when done. */
    record Times(Map<MapKey, long[]> maps, Map<DriverKey, Long> done) {
        long[] map(int replication, String driver, int mapIndex) {
            return maps.getOrDefault(new MapKey(new DriverKey(replication, driver), mapIndex), new long[2]);
        }

        long done(int replication, String driver) {
            return done.getOrDefault(new DriverKey(replication, driver), 0L);
        }
    }

    /** One map of a driver's part of a replication. */
    record MapKey(DriverKey driver, int mapIndex) {
    }

    private TimingsCsv() {
    }

    static String mapRow(int replication, String driver, int mapIndex, long mapNanos, long driverNanos) {
        return row(replication, driver, MAP, mapIndex, mapNanos, driverNanos);
    }

    static String doneRow(int replication, String driver, int maps, long driverNanos) {
        return row(replication, driver, DONE, maps, driverNanos, driverNanos);
    }

    private static String row(int replication, String driver, String event, int index, long mapNanos, long driverNanos) {
        return COLUMNS.row().set("replication", replication).set("driver", driver).set("event", event)
                .set("map_index", index).set("map_nanos", mapNanos).set("driver_nanos", driverNanos).line();
    }

    /** The times of timings.csv's whole lines, read by the names of the file's header. */
    static Times read(List<String> lines, String source, String fix) {
        if (lines.isEmpty()) {
            throw new IllegalArgumentException(source + ": expected the header " + HEADER + ", found nothing; " + fix);
        }
        Columns.Layout layout = COLUMNS.layout(lines.get(0), source, fix);
        Map<MapKey, long[]> maps = new HashMap<>();
        Map<DriverKey, Long> done = new HashMap<>();
        for (int i = 1; i < lines.size(); i++) {
            try {
                Columns.Line f = layout.split(lines.get(i));
                String event = f.get("event");
                if (!(event.equals(MAP) || event.equals(DONE))) {
                    throw new IllegalArgumentException("expected the event 'map' or 'done', found '" + event + "'");
                }
                DriverKey driver = new DriverKey(f.integer("replication"), f.get("driver"));
                long[] nanos = {f.longValue("map_nanos"), f.longValue("driver_nanos")};
                if (event.equals(MAP)) {
                    maps.put(new MapKey(driver, f.integer("map_index")), nanos);
                } else {
                    done.put(driver, nanos[1]);
                }
            } catch (IllegalArgumentException e) {
                throw new IllegalArgumentException(source + ":" + (i + 1) + ": " + e.getMessage());
            }
        }
        return new Times(maps, done);
    }
}
