package sitcov.experiment;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.function.IntConsumer;
import java.util.function.LongSupplier;
import sitcov.faults.Fault;

/**
 * The paper's effort sweep (Fig. 4): the coverage-filter driver alone at several candidate budgets,
 * several map sets each (the config's replications); for each set, the coverage it reached and the
 * faults its maps found. Map set {@code s} at budget {@code c} draws from replication stream
 * {@code c * 1000 + s}, so sets differ and every point is reproducible from the master seed.
 */
public final class Sweep {
    private Sweep() {
    }

    /** One map set of the sweep: its budget, coverage, and faults found under both notions. */
    public record Point(int candidates, int set, int maps, int cells, int faultsFound, int faultsFoundPaper,
                        double avgMapFault, double avgMapFaultPaper) {
    }

    public static List<Point> run(ExperimentConfig config, List<Integer> budgets, int threads, LongSupplier nanoClock,
                                  IntConsumer done) {
        List<Fault> faults = config.faults().stream().sorted().toList();
        List<Callable<Point>> tasks = new ArrayList<>();
        for (int budget : budgets) {
            for (int set = 0; set < config.replications(); set++) {
                int s = set;
                ExperimentConfig c = new ExperimentConfig(config.name(), config.masterSeed(), budget, config.replications(),
                        config.faults(), config.budget(), config.grid());
                tasks.add(() -> {
                    ReplicationResult r = new Replication(c, budget * 1000 + s, nanoClock).runCoverageOnly();
                    List<MapRun> runs = r.runsOf(Method.COVERAGE_FILTER);
                    Metrics d = Metrics.of(runs, faults, false);
                    Metrics p = Metrics.of(runs, faults, true);
                    return new Point(budget, s, runs.size(), d.cells(), (int) Math.round(d.methodPropFault() * faults.size()),
                            (int) Math.round(p.methodPropFault() * faults.size()), d.avgMapFault(), p.avgMapFault());
                });
            }
        }
        return InOrder.run(tasks, threads, done, "sweep " + config.name());
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
