package sitcov.analysis;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import sitcov.experiment.DriverRun;
import sitcov.experiment.DriverSpend;
import sitcov.experiment.MapRun;

/** Coverage a driver reached in a replication after a number of candidates, maps run and simulated ticks. */
public record CurvePoint(int replication, String driver, int candidates, int mapsRun, long ticks, int cellsCovered) {
    /** A point at every map that filled a new cell, and one where the driver stopped. */
    public static List<CurvePoint> of(int replication, DriverRun run) {
        List<CurvePoint> points = new ArrayList<>();
        Set<Integer> cells = new HashSet<>();
        long ticks = 0;
        int maps = 0;
        for (MapRun m : run.maps()) {
            maps++;
            ticks += m.ticks();
            if (m.cell() >= 0 && cells.add(m.cell())) {
                points.add(new CurvePoint(replication, run.driver(), m.candidate() + 1, maps, ticks, cells.size()));
            }
        }
        DriverSpend s = run.spend();
        points.add(new CurvePoint(replication, run.driver(), s.candidates(), s.mapsRun(), s.ticks(), s.cellsCovered()));
        return points;
    }
}
