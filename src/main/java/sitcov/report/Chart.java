package sitcov.report;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.geom.Path2D;
import java.util.Locale;

/** A plot panel with linear axes, drawn into part of an image: enough for the experiment's figures. */
final class Chart {
    static final Color COVERAGE = new Color(31, 119, 180);
    static final Color RANDOM = new Color(255, 127, 14);
    /** One colour per driver, in the preset's order; the paper's two keep their colours. */
    private static final Color[] DRIVERS = {COVERAGE, RANDOM, new Color(44, 160, 44), new Color(214, 39, 40),
        new Color(148, 103, 189), new Color(140, 86, 75), new Color(227, 119, 194), new Color(127, 127, 127)};

    private final Graphics2D g;
    private final int left;
    private final int top;
    private final int width;
    private final int height;
    private final double xMax;
    private final double yMax;
    private final int xTicks;

    /** A panel whose axes run to round numbers at or above the given maxima, five ticks each. */
    Chart(Graphics2D g, int left, int top, int width, int height, double xMax, double yMax) {
        this(g, left, top, width, height, nice(xMax), nice(yMax), 5);
    }

    /** A panel whose x axis runs to exactly {@code xMax} with {@code xTicks} divisions (for counts; 0: no x labels). */
    Chart(Graphics2D g, int left, int top, int width, int height, double xMax, double yMax, int xTicks) {
        this.g = g;
        this.left = left;
        this.top = top;
        this.width = width;
        this.height = height;
        this.xMax = xMax <= 0 ? 1 : xMax;
        this.yMax = yMax <= 0 ? 1 : yMax;
        this.xTicks = xTicks;
    }

    /** The smallest of 1, 2, 2.5, 5 times a power of ten that is at least {@code v}. */
    static double nice(double v) {
        if (v <= 0) {
            return 1;
        }
        double p = Math.pow(10, Math.floor(Math.log10(v)));
        for (double m : new double[] {1, 2, 2.5, 5, 10}) {
            if (m * p >= v - 1e-9) {
                return m * p;
            }
        }
        return 10 * p;
    }

    int px(double x) {
        return left + (int) Math.round(x / xMax * width);
    }

    int py(double y) {
        return top + height - (int) Math.round(y / yMax * height);
    }

    void axes(String title, String xLabel, String yLabel) {
        g.setColor(Color.BLACK);
        g.setFont(new Font(Font.SANS_SERIF, Font.BOLD, 13));
        g.drawString(title, left, top - 12);
        g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 11));
        g.setStroke(new BasicStroke(1f));
        for (int i = 0; xTicks > 0 && i <= xTicks; i++) {
            double x = xMax * i / xTicks;
            g.setColor(Color.DARK_GRAY);
            String xs = number(x);
            g.drawString(xs, px(x) - g.getFontMetrics().stringWidth(xs) / 2, top + height + 15);
        }
        for (int i = 0; i <= 5; i++) {
            double y = yMax * i / 5;
            g.setColor(new Color(230, 230, 230));
            g.drawLine(left, py(y), left + width, py(y));
            g.setColor(Color.DARK_GRAY);
            String ys = number(y);
            g.drawString(ys, left - 6 - g.getFontMetrics().stringWidth(ys), py(y) + 4);
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
        if (xs.length == 0) {
            return;
        }
        Path2D.Double path = new Path2D.Double();
        path.moveTo(px(xs[0]), py(ys[0]));
        for (int i = 1; i < xs.length; i++) {
            // coverage is a step function: it stays until the next map fills a cell
            path.lineTo(px(xs[i]), py(ys[i - 1]));
            path.lineTo(px(xs[i]), py(ys[i]));
        }
        g.setColor(colour);
        g.setStroke(new BasicStroke(weight));
        g.draw(path);
    }

    void bar(double x, double barWidth, double y, Color colour) {
        int x0 = px(x);
        int x1 = px(x + barWidth);
        g.setColor(colour);
        g.fillRect(x0, py(y), Math.max(1, x1 - x0), top + height - py(y));
    }

    void legend(int x, int y, String[] labels, Color[] colours) {
        g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 12));
        for (int i = 0; i < labels.length; i++) {
            g.setColor(colours[i]);
            g.fillRect(x, y + i * 18 - 10, 14, 10);
            g.setColor(Color.BLACK);
            g.drawString(labels[i], x + 20, y + i * 18);
        }
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

    static String number(double v) {
        if (Math.abs(v - Math.rint(v)) < 1e-9) {
            return Long.toString(Math.round(v));
        }
        return String.format(Locale.ROOT, Math.abs(v) < 10 ? "%.2f" : "%.0f", v);
    }
}
