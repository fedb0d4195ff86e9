package sitcov.figures;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.geom.Path2D;
import java.util.List;
import java.util.Locale;

/** A plot panel with linear axes from 0, drawn into part of an image: enough for the experiment's figures. */
final class Chart {
    static final Color COVERAGE = new Color(31, 119, 180);
    static final Color RANDOM = new Color(255, 127, 14);
    /** One colour per driver, in the preset's order; the paper's two keep their colours. */
    private static final Color[] DRIVERS = {COVERAGE, RANDOM, new Color(44, 160, 44), new Color(214, 39, 40),
        new Color(148, 103, 189), new Color(140, 86, 75), new Color(227, 119, 194), new Color(127, 127, 127)};
    /** Pixels between the median lines of neighbouring drivers, so that equal medians lie side by side. */
    static final double MEDIAN_SPACING = 3;

    private final Graphics2D g;
    private final int left;
    private final int top;
    private final int width;
    private final int height;
    private final Axis x;
    private final Axis y;

    /** A panel with the given axes; an x axis without labels ({@code ticks} of only 0) is left bare. */
    Chart(Graphics2D g, int left, int top, int width, int height, Axis x, Axis y) {
        this.g = g;
        this.left = left;
        this.top = top;
        this.width = width;
        this.height = height;
        this.x = x.end() > 0 ? x : Axis.steps(1, 1);
        this.y = y.end() > 0 ? y : Axis.steps(1, 1);
    }

    int px(double v) {
        return left + (int) Math.round(v / x.end() * width);
    }

    int py(double v) {
        return top + height - (int) Math.round(v / y.end() * height);
    }

    void axes(String title, String xLabel, String yLabel) {
        g.setColor(Color.BLACK);
        g.setFont(new Font(Font.SANS_SERIF, Font.BOLD, 13));
        g.drawString(title, left, top - 12);
        g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 11));
        g.setStroke(new BasicStroke(1f));
        for (double t : x.ticks().size() > 1 ? x.ticks() : List.<Double>of()) {
            g.setColor(Color.DARK_GRAY);
            String xs = x.label(t);
            g.drawString(xs, px(t) - g.getFontMetrics().stringWidth(xs) / 2, top + height + 15);
        }
        for (double t : y.ticks()) {
            g.setColor(new Color(230, 230, 230));
            g.drawLine(left, py(t), left + width, py(t));
            g.setColor(Color.DARK_GRAY);
            String ys = y.label(t);
            g.drawString(ys, left - 6 - g.getFontMetrics().stringWidth(ys), py(t) + 4);
        }
        g.setColor(Color.BLACK);
        g.drawRect(left, top, width, height);
        g.drawString(xLabel, left + width / 2 - g.getFontMetrics().stringWidth(xLabel) / 2, top + height + 32);
        Graphics2D r = (Graphics2D) g.create();
        r.rotate(-Math.PI / 2);
        r.drawString(yLabel, -(top + height / 2 + r.getFontMetrics().stringWidth(yLabel) / 2), left - 42);
        r.dispose();
    }

    void line(double[] xs, double[] ys, Color colour, float weight) {
        line(xs, ys, colour, weight, 0);
    }

    /** A step line, moved {@code shift} pixels right and up: the same values of two drivers then lie side by side. */
    void line(double[] xs, double[] ys, Color colour, float weight, double shift) {
        if (xs.length == 0) {
            return;
        }
        Path2D.Double path = new Path2D.Double();
        path.moveTo(px(xs[0]) + shift, py(ys[0]) - shift);
        for (int i = 1; i < xs.length; i++) {
            // coverage is a step function: it stays until the next map fills a cell
            path.lineTo(px(xs[i]) + shift, py(ys[i - 1]) - shift);
            path.lineTo(px(xs[i]) + shift, py(ys[i]) - shift);
        }
        Graphics2D inside = framed();
        inside.setColor(colour);
        inside.setStroke(new BasicStroke(weight));
        inside.draw(path);
        inside.dispose();
    }

    /** Drawing clipped to the frame: a line shifted past the axis's end stays inside it. */
    private Graphics2D framed() {
        Graphics2D inside = (Graphics2D) g.create();
        inside.clipRect(left, top, width + 1, height + 1);
        return inside;
    }

    /**
     * Per driver its band between the quartiles, shaded, then over all of them its median, bold and
     * shifted by {@link #shift} so that equal medians lie side by side rather than one hiding another.
     */
    void bands(List<Band> bands, Color[] colours) {
        for (int d = 0; d < bands.size(); d++) {
            Band b = bands.get(d);
            if (b.xs().length == 0) {
                continue;
            }
            Path2D.Double area = new Path2D.Double();
            area.moveTo(px(b.xs()[0]), py(b.upper()[0]));
            for (int i = 1; i < b.xs().length; i++) {
                area.lineTo(px(b.xs()[i]), py(b.upper()[i - 1]));
                area.lineTo(px(b.xs()[i]), py(b.upper()[i]));
            }
            for (int i = b.xs().length - 1; i > 0; i--) {
                area.lineTo(px(b.xs()[i]), py(b.lower()[i]));
                area.lineTo(px(b.xs()[i]), py(b.lower()[i - 1]));
            }
            area.lineTo(px(b.xs()[0]), py(b.lower()[0]));
            area.closePath();
            Graphics2D inside = framed();
            inside.setColor(faint(colours[d], 60));
            inside.fill(area);
            inside.dispose();
        }
        for (int d = 0; d < bands.size(); d++) {
            Band b = bands.get(d);
            // bold while every replication ran, thinner where some had stopped
            int all = 0;
            while (all + 1 < b.xs().length && b.xs()[all + 1] <= b.allRan()) {
                all++;
            }
            int n = b.xs().length;
            line(java.util.Arrays.copyOf(b.xs(), Math.min(n, all + 1)), java.util.Arrays.copyOf(b.median(), Math.min(n, all + 1)),
                    colours[d], 2.5f, shift(d, bands.size()));
            line(java.util.Arrays.copyOfRange(b.xs(), all, n), java.util.Arrays.copyOfRange(b.median(), all, n), colours[d],
                    1.5f, shift(d, bands.size()));
        }
    }

    /** The end of the x axis: lines that run on are cut there. */
    double xEnd() {
        return x.end();
    }

    /** The shift of driver {@code d} of {@code n}'s median line: neighbours {@link #MEDIAN_SPACING} apart, centred. */
    static double shift(int d, int n) {
        return (d - (n - 1) / 2.0) * MEDIAN_SPACING;
    }

    void bar(double at, double barWidth, double value, Color colour) {
        int x0 = px(at);
        int x1 = px(at + barWidth);
        g.setColor(colour);
        g.fillRect(x0, py(value), Math.max(1, x1 - x0), top + height - py(value));
    }

    /** A legend laid out in one row, for under the panels where it hides no data. */
    static void legendRow(Graphics2D g, int x, int y, String[] labels, Color[] colours) {
        g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 12));
        int at = x;
        for (int i = 0; i < labels.length; i++) {
            g.setColor(colours[i]);
            g.fillRect(at, y - 10, 14, 10);
            g.setColor(Color.BLACK);
            g.drawString(labels[i], at + 20, y);
            at += 20 + g.getFontMetrics().stringWidth(labels[i]) + 24;
        }
    }

    static Color driver(int index) {
        return DRIVERS[index % DRIVERS.length];
    }

    static Color[] drivers(int count) {
        Color[] colours = new Color[count];
        for (int i = 0; i < count; i++) {
            colours[i] = driver(i);
        }
        return colours;
    }

    static Color faint(Color c, int alpha) {
        return new Color(c.getRed(), c.getGreen(), c.getBlue(), alpha);
    }

    static String number(double v) {
        if (Math.abs(v - Math.rint(v)) < 1e-9) {
            return Long.toString(Math.round(v));
        }
        return String.format(Locale.ROOT, Math.abs(v) < 10 ? "%.2f" : "%.0f", v);
    }
}
