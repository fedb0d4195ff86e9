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
import sitcov.analysis.Summary;
import sitcov.analysis.Sweep;
import sitcov.experiment.ExperimentConfig;
import sitcov.judge.Notion;
import sitcov.render.MapRenderer;
import sitcov.results.OutputFile;
import sitcov.results.ResultsFolder;

/** The effort sweep's results: {@code sweep.csv}, {@code manifest.properties} and Fig. 4 (faults found against coverage, with the regression line and r²). */
public final class SweepReport {
    private SweepReport() {
    }

    public static void write(ExperimentConfig config, Summary summary, Path folder) throws IOException {
        List<Sweep.Point> points = Sweep.points(config, summary);
        List<String> rows = new ArrayList<>();
        rows.add("candidates,map_set,driver,maps_run,cells_covered,faults_found,faults_found_paper,avg_map_fault,"
                + "avg_map_fault_paper");
        for (Sweep.Point p : points) {
            rows.add(String.format(Locale.ROOT, "%d,%d,%s,%d,%d,%d,%d,%.4f,%.4f", p.candidates(), p.set(), p.driver(),
                    p.maps(), p.cells(), p.faultsFound(), p.faultsFoundPaper(), p.avgMapFault(), p.avgMapFaultPaper()));
        }
        OutputFile.writeLines(folder.resolve(ResultsFolder.SWEEP), rows);
        MapRenderer.writeAtomically(figure(config, points), folder.resolve(ResultsFolder.FIG4));
    }

    static BufferedImage figure(ExperimentConfig config, List<Sweep.Point> points) {
        BufferedImage image = new BufferedImage(1000, 440, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = image.createGraphics();
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
        g.setColor(Color.WHITE);
        g.fillRect(0, 0, 1000, 440);
        g.setColor(Color.BLACK);
        g.setFont(new Font(Font.SANS_SERIF, Font.BOLD, 15));
        g.drawString("Faults found per map against situation coverage: " + String.join(", ", config.drivers()) + ", "
                + points.size() + " map sets (" + config.name() + ")", 20, 30);
        double[] x = points.stream().mapToDouble(Sweep.Point::cells).toArray();
        double maxX = points.stream().mapToDouble(Sweep.Point::cells).max().orElse(1);
        for (int panel = 0; panel < 2; panel++) {
            boolean paper = panel == 1;
            double[] y = points.stream().mapToDouble(p -> paper ? p.avgMapFaultPaper() : p.avgMapFault()).toArray();
            double maxY = 0;
            for (double v : y) {
                maxY = Math.max(maxY, v);
            }
            Chart chart = new Chart(g, 80 + panel * 480, 80, 380, 260, Axis.counts(maxX).padded(), Axis.upTo(Math.max(1, maxY)).padded());
            chart.axes((paper ? Notion.PAPER : Notion.DIFFERENTIAL).label(),
                    "cells covered (of " + config.grid().cells() + ")", "avg-map-fault");
            double[] fit = Sweep.regression(x, y);
            g.setColor(new Color(200, 40, 40));
            g.setStroke(new java.awt.BasicStroke(2f));
            g.drawLine(chart.px(0), chart.py(fit[0]), chart.px(maxX), chart.py(fit[0] + fit[1] * maxX));
            for (int i = 0; i < x.length; i++) {
                g.setColor(Chart.driver(config.driverIndex(points.get(i).driver())));
                g.fillOval(chart.px(x[i]) - 4, chart.py(y[i]) - 4, 8, 8);
            }
            g.setColor(Color.BLACK);
            g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 12));
            g.drawString(String.format(Locale.ROOT, "y = %.3f + %.4f x,  r\u00b2 = %.3f", fit[0], fit[1], fit[2]),
                    100 + panel * 480, 100);
        }
        g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 11));
        g.drawString("each dot: one map set of a driver at one candidate budget; red: least-squares line over all dots",
                80, 410);
        g.dispose();
        return image;
    }

}
