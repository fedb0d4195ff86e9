package sitcov.results;

import java.util.ArrayList;
import java.util.List;
import sitcov.experiment.DriverSpend;
import sitcov.experiment.StopReason;

/** {@code drivers.csv}: what each driver spent in each replication and why it stopped; one row each. */
public final class DriversCsv {
    public static final Columns COLUMNS =
            Columns.of("replication", "driver", "candidates", "maps_run", "ticks", "cells_covered", "stopped_by");
    public static final String HEADER = COLUMNS.header();

    private DriversCsv() {
    }

    static String row(DriverSpend s) {
        return COLUMNS.row().set("replication", s.replication()).set("driver", s.driver()).set("candidates", s.candidates())
                .set("maps_run", s.mapsRun()).set("ticks", s.ticks()).set("cells_covered", s.cellsCovered())
                .set("stopped_by", s.stoppedBy().key()).line();
    }

    /** The rows of drivers.csv's whole lines, read by the names of the file's header. */
    static List<DriverSpend> read(List<String> lines, String source, String fix) {
        if (lines.isEmpty()) {
            throw new IllegalArgumentException(source + ": expected the header " + HEADER + ", found nothing; " + fix);
        }
        Columns.Layout layout = COLUMNS.layout(lines.get(0), source, fix);
        List<DriverSpend> spends = new ArrayList<>();
        for (int i = 1; i < lines.size(); i++) {
            try {
                Columns.Line f = layout.split(lines.get(i));
                spends.add(new DriverSpend(f.integer("replication"), f.get("driver"), f.integer("candidates"),
                        f.integer("maps_run"), f.longValue("ticks"), f.integer("cells_covered"),
                        StopReason.ofKey(f.get("stopped_by"))));
            } catch (IllegalArgumentException e) {
                throw new IllegalArgumentException(source + ":" + (i + 1) + ": " + e.getMessage());
            }
        }
        return spends;
    }
}
