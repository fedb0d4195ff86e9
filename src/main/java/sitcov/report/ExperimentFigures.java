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
import sitcov.experiment.CurvePoint;
import sitcov.experiment.ExperimentConfig;
import sitcov.experiment.MapRun;
import sitcov.experiment.Method;
import sitcov.experiment.ReplicationResult;

/**
 * The paper's figures for a comparison experiment: faults found per map by method (Fig. 2, under
 * both detection notions) and coverage against candidates and against time (Fig. 3).
 */
public final class ExperimentFigures {
    private ExperimentFigures() {
    }

    public static void writeAll(ExperimentConfig config, List<ReplicationResult> results, Path folder) throws IOException {
        MapRenderer.writeAtomically(faultsPerMap(config, results), folder.resolve("fig2-faults-per-map.png"));
        MapRenderer.writeAtomically(coverage(config, results), folder.resolve("fig3-coverage.png"));
    }

    static BufferedImage faultsPerMap(ExperimentConfig config, List<ReplicationResult> results) {
        int k = config.faults().size();
        BufferedImage image = canvas(1000, 420);
        Graphics2D g = graphics(image);
        title(g, "Faults found per map, by method (" + config.name() + ", master seed " + config.masterSeed() + ", "
                + results.size() + " replications)");
        String[] notions = {"differential oracle (new accident)", "paper's notion (any accident)"};
        for (int n = 0; n < 2; n++) {
            double[][] share = new double[2][k + 1];
            double top = 0;
            for (Method m : Method.values()) {
                List<MapRun> runs = results.stream().flatMap(r -> r.runsOf(m).stream()).toList();
                for (MapRun run : runs) {
                    share[m.ordinal()][(int) run.faultsFound(n == 1)] += 1.0 / Math.max(1, runs.size());
                }
                for (double s : share[m.ordinal()]) {
                    top = Math.max(top, s);
                }
            }
            Chart chart = new Chart(g, 80 + n * 480, 80, 380, 260, k + 1, Math.min(1, Math.ceil(top * 10) / 10), k + 1);
            chart.axes(notions[n], "faults found on the map (of " + k + ")", "share of maps");
            for (int f = 0; f <= k; f++) {
                chart.bar(f + 0.1, 0.4, share[0][f], Chart.COVERAGE);
                chart.bar(f + 0.5, 0.4, share[1][f], Chart.RANDOM);
            }
            if (n == 1) {
                chart.legend(80 + n * 480 + 240, 100, new String[] {"coverage-filter", "random"},
                        new Color[] {Chart.COVERAGE, Chart.RANDOM});
            }
        }
        g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 11));
        g.drawString("x = number of faults found on a map; bar i spans [i, i+1)", 80, 395);
        g.dispose();
        return image;
    }

    static BufferedImage coverage(ExperimentConfig config, List<ReplicationResult> results) {
        BufferedImage image = canvas(1000, 420);
        Graphics2D g = graphics(image);
        title(g, String.format(Locale.ROOT, "Situation coverage (cells of %d) against effort (%s, %d replications)",
                config.grid().cells(), config.name(), results.size()));
        double maxCandidates = 0;
        double maxSeconds = 0;
        double maxCells = 0;
        for (ReplicationResult r : results) {
            for (CurvePoint p : r.curve()) {
                maxCandidates = Math.max(maxCandidates, p.candidates());
                maxSeconds = Math.max(maxSeconds, p.seconds());
                maxCells = Math.max(maxCells, p.cellsCovered());
            }
        }
        double yMax = maxCells;
        Chart byCandidates = new Chart(g, 80, 80, 380, 260, maxCandidates, yMax);
        byCandidates.axes("against candidate maps drawn", "candidates", "cells covered");
        Chart bySeconds = new Chart(g, 560, 80, 380, 260, maxSeconds, yMax);
        bySeconds.axes("against wall-clock time", "seconds", "cells covered");
        for (ReplicationResult r : results) {
            for (Method m : Method.values()) {
                List<CurvePoint> pts = r.curve().stream().filter(p -> p.method() == m).toList();
                double[] c = pts.stream().mapToDouble(CurvePoint::candidates).toArray();
                double[] s = pts.stream().mapToDouble(CurvePoint::seconds).toArray();
                double[] y = pts.stream().mapToDouble(CurvePoint::cellsCovered).toArray();
                Color colour = m == Method.COVERAGE_FILTER ? Chart.COVERAGE : Chart.RANDOM;
                byCandidates.line(c, y, colour, 1.5f);
                bySeconds.line(s, y, colour, 1.5f);
            }
        }
        bySeconds.legend(560 + 230, 300, new String[] {"coverage-filter", "random"},
                new Color[] {Chart.COVERAGE, Chart.RANDOM});
        g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 11));
        g.setColor(Color.BLACK);
        g.drawString("one line per method and replication; the random driver runs every candidate, so it draws far fewer",
                80, 395);
        g.dispose();
        return image;
    }

    private static BufferedImage canvas(int w, int h) {
        BufferedImage image = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = image.createGraphics();
        g.setColor(Color.WHITE);
        g.fillRect(0, 0, w, h);
        g.dispose();
        return image;
    }

    private static Graphics2D graphics(BufferedImage image) {
        Graphics2D g = image.createGraphics();
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
        return g;
    }

    private static void title(Graphics2D g, String text) {
        g.setColor(Color.BLACK);
        g.setFont(new Font(Font.SANS_SERIF, Font.BOLD, 15));
        g.drawString(text, 20, 30);
    }
}
