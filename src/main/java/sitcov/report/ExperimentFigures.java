package sitcov.report;

import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.function.ToDoubleFunction;
import sitcov.experiment.CurvePoint;
import sitcov.experiment.DriverRun;
import sitcov.experiment.ExperimentConfig;
import sitcov.experiment.Journal;
import sitcov.experiment.MapRun;
import sitcov.experiment.ReplicationResult;
import sitcov.experiment.Summary;

/**
 * The paper's figures for a comparison of any number of drivers: faults found per map (Fig. 2,
 * under both detection notions), coverage against candidates and simulated ticks (Fig. 3, the same
 * for every run of the experiment) and against wall-clock time (Fig. 3 as the paper drew it; timed).
 */
final class ExperimentFigures {
    private ExperimentFigures() {
    }

    static void writeAll(ExperimentConfig config, Summary summary, Journal journal, Path folder) throws IOException {
        MapRenderer.writeAtomically(faultsPerMap(config, summary), folder.resolve(ResultsFolder.FIG2));
        MapRenderer.writeAtomically(coverage(config, summary), folder.resolve(ResultsFolder.FIG3));
        MapRenderer.writeAtomically(coverageOverTime(config, summary, journal), folder.resolve(ResultsFolder.FIG3_TIME));
    }

    static BufferedImage faultsPerMap(ExperimentConfig config, Summary summary) {
        int k = config.faults().size();
        List<String> drivers = config.drivers();
        int n = drivers.size();
        BufferedImage image = canvas(1000, 440);
        Graphics2D g = graphics(image);
        title(g, "Faults found per map, by driver (" + config.name() + ", master seed " + config.masterSeed() + ", "
                + summary.results().size() + " replications)");
        String[] notions = {"differential oracle (new accident)", "paper's notion (any accident)"};
        for (int notion = 0; notion < 2; notion++) {
            double[][] share = new double[n][k + 1];
            double top = 0;
            for (int d = 0; d < n; d++) {
                String driver = drivers.get(d);
                List<MapRun> runs = summary.results().stream().flatMap(r -> r.of(driver).maps().stream()).toList();
                for (MapRun run : runs) {
                    share[d][(int) run.faultsFound(notion == 1)] += 1.0 / Math.max(1, runs.size());
                }
                for (double s : share[d]) {
                    top = Math.max(top, s);
                }
            }
            Chart chart = new Chart(g, 80 + notion * 480, 80, 380, 260, k + 1, Math.min(1, Math.ceil(top * 10) / 10), k + 1);
            chart.axes(notions[notion], "faults found on the map (of " + k + ")", "share of maps");
            double width = 0.8 / n;
            for (int f = 0; f <= k; f++) {
                for (int d = 0; d < n; d++) {
                    chart.bar(f + 0.1 + d * width, width, share[d][f], Chart.driver(d));
                }
            }
        }
        Chart.legendRow(g, 80, 400, drivers.toArray(String[]::new), Chart.drivers(n));
        note(g, "x = number of faults found on a map; bar i spans [i, i+1), one bar per driver");
        g.dispose();
        return image;
    }

    static BufferedImage coverage(ExperimentConfig config, Summary summary) {
        BufferedImage image = canvas(1000, 440);
        Graphics2D g = graphics(image);
        title(g, String.format(Locale.ROOT, "Situation coverage (cells of %d) against effort (%s, %d replications)",
                config.grid().cells(), config.name(), summary.results().size()));
        int cut = curves(g, config, summary, 80, "against candidate maps drawn", "candidates", p -> p.candidates(), true);
        curves(g, config, summary, 560, "against simulated ticks", "ticks (fault-free and faulty runs)", p -> p.ticks(), false);
        Chart.legendRow(g, 80, 400, config.drivers().toArray(String[]::new), Chart.drivers(config.drivers().size()));
        note(g, "one line per driver and replication; a driver that runs every candidate draws far fewer"
                + (cut == 0 ? "" : "; " + cut + (cut == 1 ? " line goes" : " lines go") + " on past the candidates axis"));
        g.dispose();
        return image;
    }

    /**
     * One panel of coverage curves; returns how many lines were cut at the axis. With {@code cutOutliers},
     * a few lines that run on far beyond the rest (a search that spent its candidate limit) are cut
     * where nine in ten lines have ended, so that the rest do not huddle against the left edge.
     */
    private static int curves(Graphics2D g, ExperimentConfig config, Summary summary, int left, String title,
                              String xLabel, ToDoubleFunction<CurvePoint> x, boolean cutOutliers) {
        double maxY = 0;
        List<Double> ends = new java.util.ArrayList<>();
        for (ReplicationResult r : summary.results()) {
            for (DriverRun d : r.drivers()) {
                double end = 0;
                for (CurvePoint p : CurvePoint.of(r.replication(), d)) {
                    end = Math.max(end, x.applyAsDouble(p));
                    maxY = Math.max(maxY, p.cellsCovered());
                }
                ends.add(end);
            }
        }
        java.util.Collections.sort(ends);
        double maxX = ends.isEmpty() ? 0 : ends.get(ends.size() - 1);
        if (cutOutliers && !ends.isEmpty()) {
            double mostEnded = ends.get((int) Math.ceil(0.9 * ends.size()) - 1);
            maxX = mostEnded > 0 && mostEnded < maxX / 2 ? mostEnded : maxX;
        }
        Chart chart = new Chart(g, left, 80, 380, 260, maxX, maxY);
        chart.axes(title, xLabel, "cells covered");
        int cut = 0;
        for (ReplicationResult r : summary.results()) {
            for (DriverRun d : r.drivers()) {
                List<CurvePoint> pts = CurvePoint.of(r.replication(), d);
                double[] xs = pts.stream().mapToDouble(x).toArray();
                double[] ys = pts.stream().mapToDouble(CurvePoint::cellsCovered).toArray();
                int within = 0;
                while (within < xs.length && xs[within] <= maxX) {
                    within++;
                }
                if (within < xs.length) {
                    cut++;
                    // the line as far as the axis goes: the coverage it had there
                    xs = java.util.Arrays.copyOf(xs, within + 1);
                    ys = java.util.Arrays.copyOf(ys, within + 1);
                    xs[within] = maxX;
                    ys[within] = within > 0 ? ys[within - 1] : 0;
                }
                chart.line(xs, ys, Chart.driver(config.driverIndex(d.driver())), 1.5f);
            }
        }
        return cut;
    }

    /** Coverage against each driver's own wall-clock time, read from the journal's timings. */
    static BufferedImage coverageOverTime(ExperimentConfig config, Summary summary, Journal journal) {
        BufferedImage image = canvas(560, 440);
        Graphics2D g = graphics(image);
        title(g, "Situation coverage against wall-clock time (" + config.name() + ")");
        double maxX = 0;
        double maxY = 0;
        for (Journal.Finished f : journal.finished()) {
            maxX = Math.max(maxX, f.driverNanos() / 1e9);
            maxY = Math.max(maxY, f.spend().cellsCovered());
        }
        Chart chart = new Chart(g, 80, 80, 420, 260, maxX, maxY);
        chart.axes("cells covered against seconds the driver ran", "seconds", "cells covered");
        for (ReplicationResult r : summary.results()) {
            for (DriverRun d : r.drivers()) {
                List<Journal.Entry> entries = journal.maps(r.replication(), d.driver());
                double[] xs = new double[entries.size() + 1];
                double[] ys = new double[entries.size() + 1];
                java.util.Set<Integer> cells = new java.util.HashSet<>();
                for (int i = 0; i < entries.size(); i++) {
                    int cell = entries.get(i).run().cell();
                    if (cell >= 0) {
                        cells.add(cell);
                    }
                    xs[i] = entries.get(i).driverNanos() / 1e9;
                    ys[i] = cells.size();
                }
                xs[entries.size()] = journal.finished(r.replication(), d.driver()).map(f -> f.driverNanos() / 1e9).orElse(0.0);
                ys[entries.size()] = cells.size();
                chart.line(xs, ys, Chart.driver(config.driverIndex(d.driver())), 1.5f);
            }
        }
        Chart.legendRow(g, 80, 400, config.drivers().toArray(String[]::new), Chart.drivers(config.drivers().size()));
        note(g, "timed: differs from run to run and machine to machine");
        g.dispose();
        return image;
    }

    static void note(Graphics2D g, String text) {
        g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 11));
        g.setColor(Color.BLACK);
        g.drawString(text, 80, 425);
    }

    static BufferedImage canvas(int w, int h) {
        BufferedImage image = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = image.createGraphics();
        g.setColor(Color.WHITE);
        g.fillRect(0, 0, w, h);
        g.dispose();
        return image;
    }

    static Graphics2D graphics(BufferedImage image) {
        Graphics2D g = image.createGraphics();
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
        return g;
    }

    static void title(Graphics2D g, String text) {
        g.setColor(Color.BLACK);
        g.setFont(new Font(Font.SANS_SERIF, Font.BOLD, 15));
        g.drawString(text, 20, 30);
    }
}
