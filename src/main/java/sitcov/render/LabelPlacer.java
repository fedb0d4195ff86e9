package sitcov.render;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.FontMetrics;
import java.awt.Graphics2D;
import java.awt.geom.Line2D;
import java.awt.geom.Rectangle2D;
import java.awt.geom.RoundRectangle2D;
import java.util.ArrayList;
import java.util.List;

/**
 * Puts short text labels next to the things they name, in pixel coordinates, on a white tag so
 * they read on grass and asphalt alike. Each label takes the first spot around its anchor that
 * stays inside the picture and clear of earlier labels and reserved areas (the markers
 * themselves): eight spots round the anchor, then the same eight further out, ring by ring, with a
 * leader line back to the anchor. Where nothing is clear, it still keeps off other labels if any
 * spot does, covering a marker rather than a label's text.
 */
final class LabelPlacer {
    private final Graphics2D g;
    private final MapStyle style;
    private final Rectangle2D bounds;
    /** Rings of spots tried round an anchor, each a label's height further out than the last. */
    private static final int RINGS = 12;

    private final List<Rectangle2D> reserved = new ArrayList<>();
    private final List<Rectangle2D> labels = new ArrayList<>();

    LabelPlacer(Graphics2D g, MapStyle style, Rectangle2D bounds) {
        this.g = g;
        this.style = style;
        this.bounds = bounds;
    }

    /** Keeps labels off an area, a marker say. */
    void reserve(Rectangle2D area) {
        reserved.add(area);
    }

    /** The tags placed so far, in pixels. */
    List<Rectangle2D> placed() {
        return List.copyOf(labels);
    }

    /**
     * Draws {@code text} near ({@code x}, {@code y}), at least {@code clearance} pixels from it,
     * with an accent bar in {@code accent} and a thin leader line pointing back to the anchor that
     * stops {@code markerRadius} pixels short of it, so it does not cross the marker.
     */
    void place(String text, double x, double y, double clearance, double markerRadius, Color accent) {
        g.setFont(style.font(java.awt.Font.BOLD));
        FontMetrics fm = g.getFontMetrics();
        double pad = Math.max(2, fm.getHeight() / 5.0);
        double bar = Math.max(3, fm.getHeight() / 4.0);
        double w = fm.stringWidth(text) + 2 * pad + bar;
        double h = fm.getAscent() + fm.getDescent() + pad;
        Rectangle2D r = spot(x, y, clearance, w, h);
        labels.add(r);

        double nx = nearestX(r, x);
        double ny = nearestY(r, y);
        double distance = Math.hypot(nx - x, ny - y);
        if (distance > markerRadius + 1) {
            double f = markerRadius / distance;
            g.setStroke(new BasicStroke(1.5f));
            g.setColor(MapStyle.LABEL_BORDER);
            g.draw(new Line2D.Double(x + (nx - x) * f, y + (ny - y) * f, nx, ny));
        }
        RoundRectangle2D tag = new RoundRectangle2D.Double(r.getX(), r.getY(), w, h, pad * 2, pad * 2);
        g.setColor(MapStyle.LABEL_BACKGROUND);
        g.fill(tag);
        g.setColor(accent);
        g.fill(new Rectangle2D.Double(r.getX() + 1, r.getY() + 1, bar, h - 2));
        g.setColor(MapStyle.LABEL_BORDER);
        g.setStroke(new BasicStroke(1f));
        g.draw(tag);
        g.setColor(MapStyle.TEXT);
        g.drawString(text, (float) (r.getX() + bar + pad), (float) (r.getY() + pad / 2 + fm.getAscent()));
    }

    /**
     * The first spot of the rings round ({@code x}, {@code y}) that is inside the picture and clear
     * of everything; failing that, the one that overlaps labels least, then reserved areas least.
     */
    private Rectangle2D spot(double x, double y, double clearance, double w, double h) {
        Rectangle2D best = null;
        double bestLabels = Double.MAX_VALUE;
        double bestReserved = Double.MAX_VALUE;
        double step = Math.max(h, clearance);
        for (int ring = 0; ring < RINGS; ring++) {
            double d = clearance + ring * step;
            double[][] spots = {
                {d, -d - h}, {d, d}, {-d - w, -d - h}, {-d - w, d},
                {-w / 2, -d - h - clearance}, {-w / 2, d + clearance}, {d + clearance, -h / 2}, {-d - w - clearance, -h / 2},
            };
            for (double[] offset : spots) {
                Rectangle2D r = new Rectangle2D.Double(x + offset[0], y + offset[1], w, h);
                if (!inside(r)) {
                    r = clamp(r);
                }
                double onLabels = overlap(r, labels);
                double onReserved = overlap(r, reserved);
                if (onLabels == 0 && onReserved == 0) {
                    return r;
                }
                if (onLabels < bestLabels || onLabels == bestLabels && onReserved < bestReserved) {
                    best = r;
                    bestLabels = onLabels;
                    bestReserved = onReserved;
                }
            }
        }
        return best;
    }

    private static double overlap(Rectangle2D r, List<Rectangle2D> others) {
        double total = 0;
        for (Rectangle2D t : others) {
            Rectangle2D i = r.createIntersection(t);
            if (i.getWidth() > 0 && i.getHeight() > 0) {
                total += i.getWidth() * i.getHeight();
            }
        }
        return total;
    }

    private boolean inside(Rectangle2D r) {
        return r.getMinX() >= bounds.getMinX() + 1 && r.getMaxX() <= bounds.getMaxX() - 1
                && r.getMinY() >= bounds.getMinY() + 1 && r.getMaxY() <= bounds.getMaxY() - 1;
    }

    /** Moves a spot that sticks out of the picture back inside it. */
    private Rectangle2D clamp(Rectangle2D r) {
        double x = Math.max(bounds.getMinX() + 1, Math.min(r.getX(), bounds.getMaxX() - r.getWidth() - 1));
        double y = Math.max(bounds.getMinY() + 1, Math.min(r.getY(), bounds.getMaxY() - r.getHeight() - 1));
        return new Rectangle2D.Double(x, y, r.getWidth(), r.getHeight());
    }

    private static double nearestX(Rectangle2D r, double x) {
        return Math.max(r.getMinX(), Math.min(x, r.getMaxX()));
    }

    private static double nearestY(Rectangle2D r, double y) {
        return Math.max(r.getMinY(), Math.min(y, r.getMaxY()));
    }
}
