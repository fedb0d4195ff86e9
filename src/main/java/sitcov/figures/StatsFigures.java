package sitcov.figures;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Objects;
import java.util.Optional;
import java.util.Set;
import java.util.function.DoubleUnaryOperator;
import java.util.stream.Stream;
import sitcov.analysis.Comparison;
import sitcov.analysis.Discovery;
import sitcov.analysis.FaultComparison;
import sitcov.analysis.Finding;
import sitcov.analysis.Summary;
import sitcov.experiment.Measure;
import sitcov.experiment.ReplicationResult;
import sitcov.render.MapRenderer;
import sitcov.results.ResultsFolder;
import sitcov.stats.Descriptive;
import sitcov.verdict.FaultFindings;
import sitcov.verdict.VerdictText;

/**
 * The figures of the statistics: per pair of drivers, each fault's odds ratio of the pooled maps with
 * its CI (a forest plot, descriptive; bold where the replication-level test shows a difference), each
 * measure's replications by driver (strip plots with the median), and distinct faults found against
 * ticks (median and quartile band over replications).
 */
public final class StatsFigures {
    /** The measures drawn as strips, each under its {@link Measure#label()}. */
    private static final List<Measure> STRIPS = List.of(Measure.CELLS_COVERED, Measure.FAULTS_FOUND,
            Measure.AVG_MAP_FAULT, Measure.DISCOVERY_AREA);
    private static final double OR_MIN = 0.05;
    private static final double OR_MAX = 20;
    /** Driver names under the strips are slanted by this much when they do not fit side by side. */
    private static final double SLANT = Math.toRadians(35);

    /** Two drivers compared, {@code a} earlier in the preset, as {@link Comparison} orders them. */
    record Pair(String a, String b, boolean primary) {
    }

    private StatsFigures() {
    }

    public static void writeAll(Summary summary, Comparison comparison, Path folder) throws IOException {
        List<Pair> pairs = pairs(summary, comparison);
        Set<String> drawn = new HashSet<>();
        for (int i = 0; i < pairs.size(); i++) {
            String name = ResultsFolder.forestPlot(i + 1, pairs.get(i).a(), pairs.get(i).b());
            MapRenderer.writeAtomically(oddsRatios(comparison, pairs.get(i)), folder.resolve(name));
            drawn.add(name);
        }
        // a folder drawn before (by an older version, or before a re-report) keeps no stale forest plot
        // for the report page to show beside the new ones
        try (Stream<Path> files = Files.list(folder)) {
            for (Path f : files.toList()) {
                String name = f.getFileName().toString();
                if (ResultsFolder.isForestPlot(name) && !drawn.contains(name)) {
                    Files.deleteIfExists(f);
                }
            }
        }
        MapRenderer.writeAtomically(measures(summary), folder.resolve(ResultsFolder.FIG_MEASURES));
        MapRenderer.writeAtomically(discovery(summary), folder.resolve(ResultsFolder.FIG_DISCOVERY));
    }

    /** Every pair of drivers, the primary question's first, then the rest in the preset's order. */
    static List<Pair> pairs(Summary summary, Comparison comparison) {
        List<String> primary = comparison.plan().hasPrimary() ? comparison.plan().primaryDrivers() : List.of();
        List<String> drivers = summary.drivers();
        List<Pair> pairs = new ArrayList<>();
        for (int i = 0; i < drivers.size(); i++) {
            for (int j = i + 1; j < drivers.size(); j++) {
                boolean isPrimary = primary.contains(drivers.get(i)) && primary.contains(drivers.get(j));
                pairs.add(isPrimary ? 0 : pairs.size(), new Pair(drivers.get(i), drivers.get(j), isPrimary));
            }
        }
        return pairs;
    }

    static BufferedImage oddsRatios(Comparison comparison, Pair pair) {
        List<FaultComparison> tests = comparison.faults().stream()
                .filter(t -> t.driverA().equals(pair.a()) && t.driverB().equals(pair.b()))
                .toList();
        int rowHeight = 22;
        int top = 80;
        int left = 250;
        int width = 560;
        BufferedImage image = ExperimentFigures.canvas(1000, top + Math.max(1, tests.size()) * rowHeight + 90);
        Graphics2D g = ExperimentFigures.graphics(image);
        ExperimentFigures.title(g, "Odds of a map finding each fault: " + pair.a() + " against " + pair.b()
                + " (all maps pooled, 95 % CI, log scale)");
        if (pair.primary()) {
            g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 12));
            g.drawString("the primary question's pair of drivers", 20, 50);
        }
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
        g.drawString("odds ratio (> 1: " + pair.a() + " finds it on more of its maps; ends beyond 0.05 or 20 are clipped)",
                left, bottom + 32);
        for (int i = 0; i < tests.size(); i++) {
            FaultComparison t = tests.get(i);
            int y = top + i * rowHeight + rowHeight / 2;
            boolean differs = FaultFindings.differs(t.finding());
            g.setColor(Color.BLACK);
            g.setFont(new Font(Font.SANS_SERIF, differs ? Font.BOLD : Font.PLAIN, 12));
            g.drawString(String.format(Locale.ROOT, "fault %2d  %d/%d vs %d/%d", t.variant().id(), t.foundA(), t.mapsA(),
                    t.foundB(), t.mapsB()), 20, y + 4);
            g.drawString(t.finding().tested() ? "BH q " + VerdictText.p(t.paired().pAdjusted())
                    : t.finding() == Finding.TOO_FEW ? "too few differ" : "not testable",
                    left + width + 20, y + 4);
            Optional<String> noRatio = noRatio(t);
            if (noRatio.isPresent()) {
                g.setColor(Color.GRAY);
                g.drawString(noRatio.get(), px.applyAsInt(1) + 8, y + 4);
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
                + " replication's share, paired, screened by Benjamini-Hochberg) flags a difference", 20, image.getHeight() - 20);
        g.dispose();
        return image;
    }

    /**
     * What a fault's row says instead of an odds ratio, if it has none: found by neither driver, or on
     * every map by both (a ratio of nothing against nothing says nothing).
     */
    static Optional<String> noRatio(FaultComparison t) {
        return Double.isNaN(t.oddsRatio()) ? Optional.of(Objects.requireNonNullElse(t.note(), "no odds ratio"))
                : Optional.empty();
    }

    /** The axis of one measure's strip: counts label whole numbers, faults found end at the experiment's faults. */
    static Axis axis(Measure measure, double max, int faults) {
        Axis axis = switch (measure) {
            case FAULTS_FOUND -> Axis.toCount(faults);
            case CELLS_COVERED, MAPS_RUN -> Axis.counts(max);
            default -> Axis.upTo(max);
        };
        return axis.padded();
    }

    static BufferedImage measures(Summary summary) {
        List<String> drivers = summary.drivers();
        int panel = 230;
        int plotWidth = panel - 60;
        java.awt.FontMetrics metrics = ExperimentFigures.graphics(ExperimentFigures.canvas(1, 1))
                .getFontMetrics(new Font(Font.SANS_SERIF, Font.PLAIN, 10));
        int widest = drivers.stream().mapToInt(metrics::stringWidth).max().orElse(0);
        // names wider than a driver's strip are slanted, so that none runs into the next
        boolean slant = widest + 6 > plotWidth / Math.max(1, drivers.size());
        int below = slant ? (int) Math.ceil(widest * Math.sin(SLANT)) + 10 : 0;
        BufferedImage image = ExperimentFigures.canvas(1000, 440 + below);
        Graphics2D g = ExperimentFigures.graphics(image);
        ExperimentFigures.title(g, "Each replication's measures by driver (" + summary.results().size()
                + " replications; bar = median)");
        for (int m = 0; m < STRIPS.size(); m++) {
            double[][] values = new double[drivers.size()][];
            double max = 0;
            for (int d = 0; d < drivers.size(); d++) {
                values[d] = Comparison.values(summary, drivers.get(d), STRIPS.get(m));
                for (double v : values[d]) {
                    max = Math.max(max, v);
                }
            }
            Chart chart = new Chart(g, 70 + m * (panel + 12), 80, plotWidth, 260,
                    new Axis(List.of(0.0), drivers.size()), axis(STRIPS.get(m), max, summary.faults().size()));
            chart.axes(STRIPS.get(m).label(), "", "");
            g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 10));
            for (int d = 0; d < drivers.size(); d++) {
                String name = drivers.get(d);
                g.setColor(Color.DARK_GRAY);
                if (slant) {
                    // the name ends under its strip and runs down to the left
                    Graphics2D r = (Graphics2D) g.create();
                    r.translate(chart.px(d + 0.5) + 4, chart.py(0) + 12);
                    r.rotate(-SLANT);
                    r.drawString(name, -g.getFontMetrics().stringWidth(name), 0);
                    r.dispose();
                } else {
                    g.drawString(name, chart.px(d + 0.5) - g.getFontMetrics().stringWidth(name) / 2, chart.py(0) + 15);
                }
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
        Chart.legendRow(g, 70, image.getHeight() - 40, drivers.toArray(String[]::new), Chart.drivers(drivers.size()));
        g.dispose();
        return image;
    }

    /** The ticks every replication of every driver spent at least: where the discovery curves are all still running. */
    static long horizon(Summary summary) {
        long horizon = Long.MAX_VALUE;
        for (ReplicationResult r : summary.results()) {
            horizon = Math.min(horizon, r.drivers().stream().mapToLong(d -> d.spend().ticks()).min().orElse(0));
        }
        return summary.results().isEmpty() ? 1 : Math.max(1, horizon);
    }

    /** The ticks at which a replication's curve of faults found steps up. */
    private static double[] firstFinds(Discovery run) {
        return java.util.stream.IntStream.range(0, run.faults().size()).mapToLong(run::ticksAtFirst)
                .filter(t -> t != Discovery.NEVER).mapToDouble(t -> t).toArray();
    }

    static BufferedImage discovery(Summary summary) {
        List<String> drivers = summary.drivers();
        long horizon = horizon(summary);
        List<Band> bands = new ArrayList<>();
        for (String driver : drivers) {
            List<Discovery> found = summary.results().stream().map(r -> Discovery.of(r.of(driver), summary.faults()))
                    .toList();
            double[] xs = Band.breaks(horizon, found.stream().map(StatsFigures::firstFinds).toList());
            bands.add(Band.of(xs, found.stream().<DoubleUnaryOperator>map(run -> t -> run.foundBy((long) t))
                    .toList(), horizon));
        }
        List<String> notes = new ArrayList<>(List.of("line: median (the drivers' " + Chart.number(Chart.MEDIAN_SPACING)
                + " px apart); shaded: between the quartiles; a map counts once judged whole"));
        String same = Band.sameMedians(drivers, bands);
        if (!same.isEmpty()) {
            notes.add(same);
        }
        BufferedImage image = ExperimentFigures.canvas(760, 424 + 16 * notes.size());
        Graphics2D g = ExperimentFigures.graphics(image);
        ExperimentFigures.title(g, "Distinct faults found against simulated ticks (median and quartiles over "
                + summary.results().size() + " replications)");
        Chart chart = new Chart(g, 80, 80, 560, 260, Axis.counts(horizon),
                Axis.toCount(summary.faults().size()).padded());
        chart.axes("", "ticks spent (fault-free and faulty runs), to the least any replication spent",
                "faults found (of " + summary.faults().size() + ")");
        chart.bands(bands, Chart.drivers(drivers.size()));
        Chart.legendRow(g, 80, 400, drivers.toArray(String[]::new), Chart.drivers(drivers.size()));
        ExperimentFigures.notes(g, notes);
        g.dispose();
        return image;
    }
}
