package sitcov.cli;

import java.io.PrintStream;
import java.util.List;
import java.util.Locale;
import sitcov.analysis.Summary;
import sitcov.analysis.Sweep;
import sitcov.experiment.ExperimentConfig;
import sitcov.judge.Notion;

/** The table printed at the end of {@code run} and {@code merge}: the means of the {@link Summary}. */
final class SummaryTable {
    private SummaryTable() {
    }

    static void print(PrintStream out, ExperimentConfig config, Summary summary) {
        if (config.isSweep()) {
            List<Sweep.Point> points = Sweep.points(config, summary);
            double[] fit = Sweep.regression(points.stream().mapToDouble(Sweep.Point::cells).toArray(),
                    points.stream().mapToDouble(Sweep.Point::avgMapFault).toArray());
            out.printf(Locale.ROOT, "%s: %d map sets; avg-map-fault = %.3f + %.4f x cells covered, r^2 = %.3f%n",
                    config.name(), points.size(), fit[0], fit[1], fit[2]);
            return;
        }
        int width = Math.max(8, config.drivers().stream().mapToInt(String::length).max().orElse(0));
        out.printf(Locale.ROOT, "%s: master seed %d, %d replications, %d candidates, budget %s; means over replications%n",
                config.name(), config.masterSeed(), summary.results().size(), config.candidates(), config.budget().key());
        out.printf(Locale.ROOT, "  %-" + width + "s %-13s %8s %8s %18s %19s %14s%n", "driver", "notion", "maps", "cells",
                "method-prop-fault", "prop-map-all-fault", "avg-map-fault");
        for (String driver : config.drivers()) {
            for (Notion notion : Notion.values()) {
                Summary.Mean m = summary.mean(driver, notion);
                out.printf(Locale.ROOT, "  %-" + width + "s %-13s %8.1f %8.1f %18.3f %19.3f %14.2f%n", driver,
                        notion.key(), m.maps(), m.cells(), m.methodPropFault(), m.propMapAllFault(),
                        m.avgMapFault());
            }
        }
        int seen = summary.cellsSeen();
        out.printf(Locale.ROOT, "  cells: of the grid's %d, %d were seen by some driver in some replication (coverage of those:"
                + " %s)%n", config.grid().cells(), seen, String.join(", ", config.drivers().stream().map(d -> String.format(
                        Locale.ROOT, "%s %.1f %%", d, seen == 0 ? 0 : 100 * summary.mean(d, Notion.DIFFERENTIAL).cells() / seen)).toList()));
    }
}
