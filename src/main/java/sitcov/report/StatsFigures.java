package sitcov.report;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.geom.Path2D;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import sitcov.experiment.Comparison;
import sitcov.experiment.Discovery;
import sitcov.experiment.FaultTest;
import sitcov.experiment.Measure;
import sitcov.experiment.ReplicationResult;
import sitcov.experiment.Summary;
import sitcov.stats.Descriptive;

/**
 * The figures of the statistics: per-fault odds ratios of the pooled maps with their CIs (a forest
 * plot of the primary question's pair of drivers, descriptive; bold where the replication-level test shows a difference), each measure's replications by driver (strip plots with the median), and distinct
 * faults found against ticks (median and quartile band over replications).
 */
final class StatsFigures {
    private static final Strip[] STRIPS = {
        new Strip(Measure.CELLS_COVERED, "cells covered"),
        new Strip(Measure.FAULTS_FOUND, "distinct faults found"),
        new Strip(Measure.AVG_MAP_FAULT, "faults found per map"),
        new Strip(Measure.DISCOVERY_AREA, "area under faults-vs-ticks")};
    /** Points at which the discovery curves are read, from no ticks to the shortest horizon. */
    private static final int CURVE_POINTS = 200;
    private static final double OR_MIN = 0.05;
    private static final double OR_MAX = 20;

    private record Strip(Measure measure, String label) {
    }

    private StatsFigures() {
    }

    static void writeAll(Summary summary, Comparison comparison, Path folder) throws IOException {
        MapRenderer.writeAtomically(oddsRatios(summary, comparison), folder.resolve(ResultsFolder.FIG_FORESTPLOT));
        MapRenderer.writeAtomically(measures(summary), folder.resolve(ResultsFolder.FIG_MEASURES));
        MapRenderer.writeAtomically(discovery(summary), folder.resolve(ResultsFolder.FIG_DISCOVERY));
    }

    static BufferedImage oddsRatios(Summary summary, Comparison comparison) {
        // the primary question's pair (the first two drivers unless the preset names another)
        List<String> pair = comparison.plan().hasPrimary() ? comparison.plan().primaryDrivers()
                : summary.drivers().subList(0, Math.min(2, summary.drivers().size()));
        List<FaultTest> tests = comparison.faults().stream()
                .filter(t -> pair.contains(t.driverA()) && pair.contains(t.driverB()))
                .toList();
        int rowHeight = 22;
        int top = 80;
        int left = 250;
        int width = 560;
        BufferedImage image = ExperimentFigures.canvas(1000, top + Math.max(1, tests.size()) * rowHeight + 90);
        Graphics2D g = ExperimentFigures.graphics(image);
        String a = tests.isEmpty() ? "?" : tests.get(0).driverA();
        String b = tests.isEmpty() ? "?" : tests.get(0).driverB();
        ExperimentFigures.title(g, "Odds of a map finding each fault: " + a + " against " + b
                + " (all maps pooled, 95 % CI, log scale)");
        double lo = Math.log(OR_MIN);
        double span = Math.log(OR_MAX) - lo;
        java.util.function.DoubleToIntFunction px = or -> left
                + (int) Math.round((Math.log(Math.max(OR_MIN, Math.min(OR_MAX, or))) - lo) / span * width);
        int bottom = top + tests.size() * rowHeight;
        g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 11));
        for (double tick : new double[] {0.05, 0.1, 0.2, 0.5, 1, 2, 5, 10, 20}) {
            g.setColor(tick == 1 ? Color.BLACK : new Color(225, 225, 225));
            g.drawLine(px.applyAsInt(tick), top - 6, px.applyAsInt(tick), bottom);
            g.setColor(Color.DARK_GRAY);
            String s = Chart.number(tick);
            g.drawString(s, px.applyAsInt(tick) - g.getFontMetrics().stringWidth(s) / 2, bottom + 15);
        }
        g.drawString("odds ratio (> 1: " + a + " finds it on more of its maps; ends beyond 0.05 or 20 are clipped)",
                left, bottom + 32);
        for (int i = 0; i < tests.size(); i++) {
            FaultTest t = tests.get(i);
            int y = top + i * rowHeight + rowHeight / 2;
            boolean differs = FaultFindings.differs(t.finding());
            g.setColor(Color.BLACK);
            g.setFont(new Font(Font.SANS_SERIF, differs ? Font.BOLD : Font.PLAIN, 12));
            g.drawString(String.format(Locale.ROOT, "fault %2d  %d/%d vs %d/%d", t.fault().id(), t.foundA(), t.mapsA(),
                    t.foundB(), t.mapsB()), 20, y + 4);
            g.drawString(t.finding().tested() ? "Holm p " + VerdictText.p(t.paired().pAdjusted())
                    : t.finding() == sitcov.experiment.Finding.TOO_FEW ? "too few differ" : "not testable",
                    left + width + 20, y + 4);
            if (Double.isNaN(t.oddsRatio())) {
                g.setColor(Color.GRAY);
                g.drawString(t.note(), px.applyAsInt(1) + 8, y + 4);
                continue;
            }
            g.setColor(differs ? Chart.COVERAGE : Color.GRAY);
            g.setStroke(new BasicStroke(2f));
            g.drawLine(px.applyAsInt(t.oddsLow()), y, px.applyAsInt(t.oddsHigh()), y);
            int x = px.applyAsInt(t.oddsRatio());
            g.fillRect(x - 4, y - 4, 9, 9);
        }
        g.setColor(Color.BLACK);
        g.drawString("maps finding it / maps run over all replications; bold, blue: the replication-level test (each"
                + " replication's share, paired, Holm) shows a difference", 20, image.getHeight() - 20);
        g.dispose();
        return image;
    }

    static BufferedImage measures(Summary summary) {
        List<String> drivers = summary.drivers();
        BufferedImage image = ExperimentFigures.canvas(1000, 440);
        Graphics2D g = ExperimentFigures.graphics(image);
        ExperimentFigures.title(g, "Each replication's measures by driver (" + summary.results().size()
                + " replications; bar = median)");
        int panel = 230;
        for (int m = 0; m < STRIPS.length; m++) {
            double[][] values = new double[drivers.size()][];
            double max = 0;
            for (int d = 0; d < drivers.size(); d++) {
                values[d] = Comparison.values(summary, drivers.get(d), STRIPS[m].measure());
                for (double v : values[d]) {
                    max = Math.max(max, v);
                }
            }
            Chart chart = new Chart(g, 70 + m * (panel + 12), 80, panel - 60, 260, drivers.size(), Chart.nice(max), 0);
            chart.axes(STRIPS[m].label(), "", "");
            g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 10));
            // names wider than a driver's strip take two rows, every other one lower, so none runs into the next
            int slot = chart.px(1) - chart.px(0);
            boolean stagger = drivers.stream().anyMatch(n -> g.getFontMetrics().stringWidth(n) + 4 > slot);
            for (int d = 0; d < drivers.size(); d++) {
                String name = drivers.get(d);
                g.setColor(Color.DARK_GRAY);
                g.drawString(name, chart.px(d + 0.5) - g.getFontMetrics().stringWidth(name) / 2,
                        chart.py(0) + 15 + (stagger && d % 2 == 1 ? 12 : 0));
            }
            for (int d = 0; d < drivers.size(); d++) {
                g.setColor(Chart.driver(d));
                double[] v = values[d];
                for (int r = 0; r < v.length; r++) {
                    // spread points across the strip by replication order: no randomness in a figure
                    double x = d + 0.25 + 0.5 * (v.length == 1 ? 0.5 : (double) r / (v.length - 1));
                    g.fillOval(chart.px(x) - 3, chart.py(v[r]) - 3, 6, 6);
                }
                if (v.length > 0) {
                    g.setColor(Color.BLACK);
                    g.setStroke(new BasicStroke(2.5f));
                    int y = chart.py(Descriptive.median(v));
                    g.drawLine(chart.px(d + 0.15), y, chart.px(d + 0.85), y);
                }
            }
        }
        Chart.legendRow(g, 70, 400, drivers.toArray(String[]::new), Chart.drivers(drivers.size()));
        g.dispose();
        return image;
    }

    static BufferedImage discovery(Summary summary) {
        List<String> drivers = summary.drivers();
        BufferedImage image = ExperimentFigures.canvas(760, 440);
        Graphics2D g = ExperimentFigures.graphics(image);
        long horizon = Long.MAX_VALUE;
        for (ReplicationResult r : summary.results()) {
            horizon = Math.min(horizon, r.drivers().stream().mapToLong(d -> d.spend().ticks()).min().orElse(0));
        }
        horizon = summary.results().isEmpty() ? 1 : Math.max(1, horizon);
        ExperimentFigures.title(g, "Distinct faults found against simulated ticks (median and quartiles over "
                + summary.results().size() + " replications)");
        Chart chart = new Chart(g, 80, 80, 560, 260, horizon, summary.faults().size());
        chart.axes("", "ticks spent (fault-free and faulty runs), to the least any replication spent",
                "faults found (of " + summary.faults().size() + ")");
        for (int d = 0; d < drivers.size(); d++) {
            double[] xs = new double[CURVE_POINTS + 1];
            double[][] band = new double[3][CURVE_POINTS + 1];
            String driver = drivers.get(d);
            List<Discovery> runs = summary.results().stream().map(r -> Discovery.of(r.of(driver), summary.faults()))
                    .toList();
            for (int i = 0; i <= CURVE_POINTS; i++) {
                long t = horizon * i / CURVE_POINTS;
                xs[i] = t;
                double[] found = runs.stream().mapToDouble(run -> run.foundBy(t)).toArray();
                Descriptive.Quartiles q = Descriptive.quartiles(found);
                band[0][i] = q.lower();
                band[1][i] = q.median();
                band[2][i] = q.upper();
            }
            Color c = Chart.driver(d);
            Path2D.Double area = new Path2D.Double();
            area.moveTo(chart.px(xs[0]), chart.py(band[2][0]));
            for (int i = 1; i < xs.length; i++) {
                area.lineTo(chart.px(xs[i]), chart.py(band[2][i]));
            }
            for (int i = xs.length - 1; i >= 0; i--) {
                area.lineTo(chart.px(xs[i]), chart.py(band[0][i]));
            }
            area.closePath();
            g.setColor(new Color(c.getRed(), c.getGreen(), c.getBlue(), 60));
            g.fill(area);
            chart.line(xs, band[1], c, 2.5f);
        }
        Chart.legendRow(g, 80, 400, drivers.toArray(String[]::new), Chart.drivers(drivers.size()));
        ExperimentFigures.note(g, "line: median; shaded: between the quartiles; a map counts once it was judged whole");
        g.dispose();
        return image;
    }
}
