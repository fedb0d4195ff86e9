package sitcov.results;

import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * {@code timings.csv}: the wall time of every judged map ({@code map} rows: the map's nanoseconds
 * and the driver's elapsed nanoseconds when it was done) and of every driver ({@code done} rows).
 * A resumed wall-clock budget continues from these.
 */
public final class TimingsCsv {
    public static final String HEADER = "replication,driver,event,map_index,map_nanos,driver_nanos";

    /** The wall times read from a timings file, keyed by replication, driver and map index (or "done"). */
    record Times(Map<String, long[]> byKey) {
        long[] map(int replication, String driver, int mapIndex) {
            return byKey.getOrDefault(key(replication, driver, Integer.toString(mapIndex)), new long[2]);
        }

        long done(int replication, String driver) {
            return byKey.getOrDefault(key(replication, driver, "done"), new long[2])[1];
        }
    }

    private TimingsCsv() {
    }

    static String mapRow(int replication, String driver, int mapIndex, long mapNanos, long driverNanos) {
        return replication + "," + driver + ",map," + mapIndex + "," + mapNanos + "," + driverNanos + "\n";
    }

    static String doneRow(int replication, String driver, int maps, long driverNanos) {
        return replication + "," + driver + ",done," + maps + "," + driverNanos + "," + driverNanos + "\n";
    }

    private static String key(int replication, String driver, String what) {
        return replication + "/" + driver + "/" + what;
    }

    static Times read(List<String> lines, String source) {
        if (lines.isEmpty() || !lines.get(0).equals(HEADER)) {
            throw new IllegalArgumentException(source + ": expected the header " + HEADER);
        }
        Map<String, long[]> times = new HashMap<>();
        for (int i = 1; i < lines.size(); i++) {
            String[] f = lines.get(i).split(",", -1);
            try {
                if (f.length != 6 || !(f[2].equals("map") || f[2].equals("done"))) {
                    throw new IllegalArgumentException("expected 'replication,driver,map|done,index,nanos,nanos'");
                }
                String what = f[2].equals("map") ? f[3] : "done";
                times.put(key(Integer.parseInt(f[0]), f[1], what), new long[] {Long.parseLong(f[4]), Long.parseLong(f[5])});
            } catch (IllegalArgumentException e) {
                throw new IllegalArgumentException(source + ":" + (i + 1) + ": " + e.getMessage());
            }
        }
        return new Times(times);
    }
}
