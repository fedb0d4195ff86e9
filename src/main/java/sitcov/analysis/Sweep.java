package sitcov.analysis;

import java.util.ArrayList;
import java.util.List;
import sitcov.experiment.DriverRun;
import sitcov.experiment.ExperimentConfig;
import sitcov.experiment.PlannedReplication;
import sitcov.experiment.ReplicationResult;
import sitcov.judge.Notion;

/**
 * The paper's effort sweep (Fig. 4): each driver at several candidate budgets, several map sets
 * each; for each set, the coverage it reached and the faults its maps found.
 */
public final class Sweep {
    private Sweep() {
    }

    /** One map set of one driver at one budget: its coverage and faults found under both notions. */
    public record Point(int candidates, int set, String driver, int maps, int cells, int faultsFound,
                        int faultsFoundPaper, double avgMapFault, double avgMapFaultPaper) {
    }

    /** The points of a sweep's results, in plan order, drivers in the preset's order within a set. */
    public static List<Point> points(ExperimentConfig config, Summary summary) {
        List<PlannedReplication> plan = config.plan();
        int k = config.variants().size();
        List<Point> points = new ArrayList<>();
        for (ReplicationResult r : summary.results()) {
            PlannedReplication p = plan.get(r.replication());
            for (DriverRun d : r.drivers()) {
                Metrics m = summary.metrics(r.replication(), d.driver(), Notion.DIFFERENTIAL);
                Metrics q = summary.metrics(r.replication(), d.driver(), Notion.PAPER);
                points.add(new Point(p.sweepBudget(), p.set(), d.driver(), m.maps(), m.cells(),
                        (int) Math.round(m.methodPropFault() * k), (int) Math.round(q.methodPropFault() * k),
                        m.avgMapFault(), q.avgMapFault()));
            }
        }
        return points;
    }

    /** Least-squares line y = a + b·x and its r², as {a, b, r²}. */
    public static double[] regression(double[] x, double[] y) {
        int n = x.length;
        double mx = 0;
        double my = 0;
        for (int i = 0; i < n; i++) {
            mx += x[i] / n;
            my += y[i] / n;
        }
        double sxy = 0;
        double sxx = 0;
        double syy = 0;
        for (int i = 0; i < n; i++) {
            sxy += (x[i] - mx) * (y[i] - my);
            sxx += (x[i] - mx) * (x[i] - mx);
            syy += (y[i] - my) * (y[i] - my);
        }
        double b = sxx == 0 ? 0 : sxy / sxx;
        double r2 = sxx == 0 || syy == 0 ? 0 : sxy * sxy / (sxx * syy);
        return new double[] {my - b * mx, b, r2};
    }
}
