package sitcov.figures;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import sitcov.analysis.CampaignAnalysis;
import sitcov.analysis.CampaignTrial;
import sitcov.experiment.CampaignTarget;
import sitcov.render.MapRenderer;
import sitcov.stats.KaplanMeier;

/**
 * A campaign's figure (experiments/README.md, "Campaigns: falsifying one version"): per target a small panel of the
 * Kaplan–Meier curves of the share of trials not yet falsified against ticks, one curve per driver, a
 * tick mark where a trial was censored (its budget spent, or it stopped, without a failure).
 */
public final class CampaignFigure {
    public static final String FILE = sitcov.results.ResultsFolder.CAMPAIGN_FIGURE;
    private static final int COLUMNS = 4;
    private static final int PANEL_W = 260;
    private static final int PANEL_H = 170;
    private static final int GAP_W = 90;
    private static final int GAP_H = 95;
    private static final int LEFT = 70;
    private static final int TOP = 95;

    private CampaignFigure() {
    }

    public static void write(CampaignAnalysis a, Path folder) throws IOException {
        MapRenderer.writeAtomically(render(a), folder.resolve(FILE));
    }

    static BufferedImage render(CampaignAnalysis a) {
        List<CampaignTarget> faults = a.config().targets();
        List<String> drivers = a.config().drivers();
        int cols = Math.min(COLUMNS, faults.size());
        int rows = (faults.size() + cols - 1) / cols;
        int w = Math.max(760, LEFT + cols * (PANEL_W + GAP_W));
        int h = TOP + rows * (PANEL_H + GAP_H);
        BufferedImage image = ExperimentFigures.canvas(w, h);
        Graphics2D g = ExperimentFigures.graphics(image);
        try {
            ExperimentFigures.title(g, "Share of trials not yet falsified against simulated ticks (Kaplan–Meier)");
            Chart.legendRow(g, 20, 55, drivers.toArray(String[]::new), Chart.drivers(drivers.size()));
            g.setColor(Color.DARK_GRAY);
            g.drawString(a.config().trials() + " trials per driver and " + a.config().noun() + "; a bar | marks a trial censored (its "
                    + a.config().tickBudget() + " ticks spent, or stopped, with no failure)", 20, 75);
            // both axes padded: a curve at 1, or a censored trial at the budget, stays inside the frame
            // in thousands of ticks, so the labels of a budget of 100 000s fit under a small panel
            Axis x = Axis.upTo(a.config().tickBudget() / THOUSAND).padded();
            Axis y = Axis.steps(0.25, 4).padded();
            for (int i = 0; i < faults.size(); i++) {
                CampaignTarget f = faults.get(i);
                int left = LEFT + (i % cols) * (PANEL_W + GAP_W);
                int top = TOP + 20 + (i / cols) * (PANEL_H + GAP_H);
                Chart chart = new Chart(g, left, top, PANEL_W, PANEL_H, x, y);
                chart.axes(f.title(), "thousand ticks", "not yet falsified");
                for (int d = 0; d < drivers.size(); d++) {
                    List<CampaignTrial> trials = CampaignAnalysis.of(a.trials(), f, drivers.get(d));
                    curve(chart, g, trials, a.config().tickBudget(), Chart.driver(d), Chart.shift(d, drivers.size()));
                }
            }
        } finally {
            g.dispose();
        }
        return image;
    }

    private static final double THOUSAND = 1000.0;

    private static void curve(Chart chart, Graphics2D g, List<CampaignTrial> trials, long budget, Color colour,
                              double shift) {
        List<KaplanMeier.Step> steps = KaplanMeier.curve(trials.stream().map(CampaignTrial::observation).toList());
        double[] xs = new double[steps.size() + 2];
        double[] ys = new double[steps.size() + 2];
        xs[0] = 0;
        ys[0] = 1;
        for (int i = 0; i < steps.size(); i++) {
            xs[i + 1] = steps.get(i).time() / THOUSAND;
            ys[i + 1] = steps.get(i).survival();
        }
        xs[xs.length - 1] = budget / THOUSAND;
        ys[ys.length - 1] = steps.isEmpty() ? 1 : steps.get(steps.size() - 1).survival();
        chart.line(xs, ys, colour, 2f, shift);
        g.setColor(colour);
        g.setStroke(new BasicStroke(1.5f));
        for (CampaignTrial t : trials) {
            if (!t.falsified()) {
                double s = KaplanMeier.survivalAt(steps, t.survivalTicks());
                int px = (int) Math.round(chart.px(t.survivalTicks() / THOUSAND) + shift);
                int py = (int) Math.round(chart.py(s) - shift);
                g.drawLine(px, py - 5, px, py + 5);
            }
        }
    }
}
