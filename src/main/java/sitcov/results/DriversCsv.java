package sitcov.results;

import java.util.ArrayList;
import java.util.List;
import sitcov.experiment.DriverSpend;
import sitcov.experiment.StopReason;

/** {@code drivers.csv}: what each driver spent in each replication and why it stopped; one row each. */
public final class DriversCsv {
    public static final String HEADER = "replication,driver,candidates,maps_run,ticks,cells_covered,stopped_by";

    private DriversCsv() {
    }

    static String row(DriverSpend s) {
        return s.replication() + "," + s.driver() + "," + s.candidates() + "," + s.mapsRun() + "," + s.ticks() + ","
                + s.cellsCovered() + "," + s.stoppedBy().key() + "\n";
    }

    static List<DriverSpend> read(List<String> lines, String source) {
        if (lines.isEmpty() || !lines.get(0).equals(HEADER)) {
            throw new IllegalArgumentException(source + ": expected the header " + HEADER);
        }
        List<DriverSpend> spends = new ArrayList<>();
        for (int i = 1; i < lines.size(); i++) {
            String[] f = lines.get(i).split(",", -1);
            try {
                if (f.length != 7) {
                    throw new IllegalArgumentException("expected 7 columns, found " + f.length);
                }
                spends.add(new DriverSpend(Integer.parseInt(f[0]), f[1], Integer.parseInt(f[2]), Integer.parseInt(f[3]),
                        Long.parseLong(f[4]), Integer.parseInt(f[5]), StopReason.ofKey(f[6])));
            } catch (IllegalArgumentException e) {
                throw new IllegalArgumentException(source + ":" + (i + 1) + ": " + e.getMessage());
            }
        }
        return spends;
    }
}
