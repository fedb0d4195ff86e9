package sitcov.figures;

import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.function.ToDoubleFunction;
import java.util.stream.Stream;
import sitcov.analysis.CurvePoint;
import sitcov.analysis.Summary;
import sitcov.experiment.DriverRun;
import sitcov.experiment.ExperimentConfig;
import sitcov.experiment.Journal;
import sitcov.experiment.MapRun;
import sitcov.experiment.ReplicationResult;
import sitcov.judge.Notion;
import sitcov.render.MapRenderer;
import sitcov.results.ResultsFolder;

/**
 * The paper's figures for a comparison of any number of drivers: faults found per map (Fig. 2,
 * under both detection notions), coverage against candidates and simulated ticks (Fig. 3, the same
 * for every run of the experiment) and against wall-clock time (Fig. 3 as the paper drew it; timed).
 */
public final class ExperimentFigures {
    private ExperimentFigures() {
    }

    public static void writeAll(ExperimentConfig config, Summary summary, Journal journal, Path folder) throws IOException {
        MapRenderer.writeAtomically(faultsPerMap(config, summary), folder.resolve(ResultsFolder.FIG2));
        MapRenderer.writeAtomically(coverage(config, summary), folder.resolve(ResultsFolder.FIG3));
        MapRenderer.writeAtomically(coverageOverTime(config, summary, journal), folder.resolve(ResultsFolder.FIG3_TIME));
    }

    static BufferedImage faultsPerMap(ExperimentConfig config, Summary summary) {
        int k = config.variants().size();
        List<String> drivers = config.drivers();
        int n = drivers.size();
        BufferedImage image = canvas(1000, 440);
        Graphics2D g = graphics(image);
        title(g, "Faults found per map, by driver (" + config.name() + ", master seed " + config.masterSeed() + ", "
                + summary.results().size() + " replications)");
        for (Notion notion : Notion.values()) {
            double[][] share = new double[n][k + 1];
            double top = 0;
            for (int d = 0; d < n; d++) {
                String driver = drivers.get(d);
                List<MapRun> runs = summary.results().stream().flatMap(r -> r.of(driver).maps().stream()).toList();
                for (MapRun run : runs) {
                    share[d][(int) run.faultsFound(notion)] += 1.0 / Math.max(1, runs.size());
                }
                for (double s : share[d]) {
                    top = Math.max(top, s);
                }
            }
            Chart chart = new Chart(g, 80 + notion.ordinal() * 480, 80, 380, 260, Axis.steps(1, k + 1),
                    Axis.upTo(Math.min(1, top)).padded());
            chart.axes(notion.label(), "faults found on the map (of " + k + ")", "share of maps");
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
        List<Curve> byCandidates = curves(config, summary, CurvePoint::candidates);
        List<Curve> byTicks = curves(config, summary, CurvePoint::ticks);
        double maxY = Stream.concat(byCandidates.stream(), byTicks.stream())
                .flatMapToDouble(c -> java.util.Arrays.stream(c.ys())).max().orElse(0);
        Axis y = Axis.counts(maxY).padded();
        Axis candidatesAxis = Axis.counts(reach(byCandidates, true));
        Axis ticksAxis = Axis.counts(reach(byTicks, false));
        List<Band> candidateBands = bands(config, byCandidates, candidatesAxis.end());
        List<Band> tickBands = bands(config, byTicks, ticksAxis.end());
        long cut = byCandidates.stream().filter(c -> c.end() > candidatesAxis.end()).count();
        List<String> notes = new ArrayList<>(BANDS);
        for (List<Band> bands : List.of(candidateBands, tickBands)) {
            String same = Band.sameMedians(config.drivers(), bands);
            if (!same.isEmpty()) {
                notes.add((bands == candidateBands ? "against candidates: " : "against ticks: ") + same);
            }
        }
        notes.add("a driver that runs every candidate draws far fewer" + (cut == 0 ? ""
                : "; " + cut + (cut == 1 ? " line goes" : " lines go") + " on past the candidates axis"));
        BufferedImage image = canvas(1000, 424 + 16 * notes.size());
        Graphics2D g = graphics(image);
        title(g, String.format(Locale.ROOT, "Situation coverage (cells of %d) against effort (%s, %d replications)",
                config.grid().cells(), config.name(), summary.results().size()));
        Chart candidates = new Chart(g, 80, 80, 380, 260, candidatesAxis, y);
        candidates.axes("against candidate maps drawn", "candidates", "cells covered");
        panel(candidates, byCandidates, candidateBands);
        Chart ticks = new Chart(g, 560, 80, 380, 260, ticksAxis, y);
        ticks.axes("against simulated ticks", "ticks (fault-free and faulty runs)", "cells covered");
        panel(ticks, byTicks, tickBands);
        Chart.legendRow(g, 80, 400, config.drivers().toArray(String[]::new), Chart.drivers(config.drivers().size()));
        notes(g, notes);
        g.dispose();
        return image;
    }

    /** What the coverage figures draw, said under them. */
    private static final List<String> BANDS = List.of("faint: each replication; bold: the median over its replications"
            + " (drivers " + Chart.number(Chart.MEDIAN_SPACING) + " px apart);", "shaded: between the quartiles; thinner"
            + " where some had stopped (a stopped one counts with its cells)");

    /** One replication's coverage of one driver: {@code ys[i]} cells from {@code xs[i]} on (ascending); it stopped at the last. */
    private record Curve(int driver, double[] xs, double[] ys) {
        double end() {
            return xs.length == 0 ? 0 : xs[xs.length - 1];
        }
    }

    private static List<Curve> curves(ExperimentConfig config, Summary summary, ToDoubleFunction<CurvePoint> x) {
        List<Curve> curves = new ArrayList<>();
        for (ReplicationResult r : summary.results()) {
            for (DriverRun d : r.drivers()) {
                List<CurvePoint> pts = CurvePoint.of(r.replication(), d);
                curves.add(new Curve(config.driverIndex(d.driver()), pts.stream().mapToDouble(x).toArray(),
                        pts.stream().mapToDouble(CurvePoint::cellsCovered).toArray()));
            }
        }
        return curves;
    }

    /**
     * How far the x axis must reach: the longest curve. With {@code cutOutliers}, a few curves that run on
     * far beyond the rest (a search that spent its candidate limit) are cut where nine in ten have ended,
     * so that the rest do not huddle against the left edge.
     */
    private static double reach(List<Curve> curves, boolean cutOutliers) {
        double[] ends = curves.stream().mapToDouble(Curve::end).sorted().toArray();
        double max = ends.length == 0 ? 0 : ends[ends.length - 1];
        if (cutOutliers && ends.length > 0) {
            double mostEnded = ends[(int) Math.ceil(0.9 * ends.length) - 1];
            return mostEnded > 0 && mostEnded < max / 2 ? mostEnded : max;
        }
        return max;
    }

    /**
     * Per driver the median and quartiles of its replications' curves, as far as the longest ran (or the
     * axis goes); a replication that had stopped counts with the cells it covered.
     */
    private static List<Band> bands(ExperimentConfig config, List<Curve> curves, double axisEnd) {
        List<Band> bands = new ArrayList<>();
        for (int d = 0; d < config.drivers().size(); d++) {
            int driver = d;
            List<Curve> mine = curves.stream().filter(c -> c.driver() == driver).toList();
            double longest = Math.min(axisEnd, mine.stream().mapToDouble(Curve::end).max().orElse(0));
            double all = mine.stream().mapToDouble(Curve::end).min().orElse(0);
            double[] xs = Band.breaks(longest, mine.stream().map(Curve::xs).toList());
            bands.add(Band.of(xs, mine.stream().map(c -> Band.steps(c.xs(), c.ys())).toList(), all));
        }
        return bands;
    }

    /** One panel of coverage curves: every replication's faint, cut at the axis's end, under the drivers' bands. */
    private static void panel(Chart chart, List<Curve> curves, List<Band> bands) {
        for (Curve c : curves) {
            double[] xs = c.xs();
            double[] ys = c.ys();
            int within = 0;
            while (within < xs.length && xs[within] <= chart.xEnd()) {
                within++;
            }
            if (within < xs.length) {
                // the line as far as the axis goes: the coverage it had there
                xs = java.util.Arrays.copyOf(xs, within + 1);
                ys = java.util.Arrays.copyOf(ys, within + 1);
                xs[within] = chart.xEnd();
                ys[within] = within > 0 ? ys[within - 1] : 0;
            }
            chart.line(xs, ys, Chart.faint(Chart.driver(c.driver()), 90), 1f);
        }
        chart.bands(bands, Chart.drivers(bands.size()));
    }

    /** Coverage against each driver's own wall-clock time, read from the journal's timings. */
    static BufferedImage coverageOverTime(ExperimentConfig config, Summary summary, Journal journal) {
        List<Curve> curves = new ArrayList<>();
        double maxY = 0;
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
                xs[entries.size()] = journal.finished(r.replication(), d.driver()).map(f -> f.driverNanos() / 1e9)
                        .orElse(entries.isEmpty() ? 0.0 : xs[entries.size() - 1]);
                ys[entries.size()] = cells.size();
                maxY = Math.max(maxY, cells.size());
                curves.add(new Curve(config.driverIndex(d.driver()), xs, ys));
            }
        }
        Axis x = Axis.upTo(reach(curves, false));
        List<Band> bands = bands(config, curves, x.end());
        List<String> notes = new ArrayList<>(BANDS);
        String same = Band.sameMedians(config.drivers(), bands);
        if (!same.isEmpty()) {
            notes.add(same);
        }
        notes.add("timed: differs from run to run and machine to machine");
        BufferedImage image = canvas(760, 424 + 16 * notes.size());
        Graphics2D g = graphics(image);
        title(g, "Situation coverage against wall-clock time (" + config.name() + ")");
        Chart chart = new Chart(g, 80, 80, 560, 260, x, Axis.counts(maxY).padded());
        chart.axes("cells covered against seconds the driver ran", "seconds", "cells covered");
        panel(chart, curves, bands);
        Chart.legendRow(g, 80, 400, config.drivers().toArray(String[]::new), Chart.drivers(config.drivers().size()));
        notes(g, notes);
        g.dispose();
        return image;
    }

    static void note(Graphics2D g, String text) {
        notes(g, List.of(text));
    }

    /** Lines of notes under a figure's legend, 16 pixels apart: the canvas needs 424 + 16 per line. */
    static void notes(Graphics2D g, List<String> lines) {
        g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 11));
        g.setColor(Color.BLACK);
        for (int i = 0; i < lines.size(); i++) {
            g.drawString(lines.get(i), 80, 425 + 16 * i);
        }
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
