package sitcov.render;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.FontMetrics;
import java.awt.Graphics2D;
import java.awt.geom.Line2D;
import java.awt.geom.Path2D;
import java.awt.geom.Rectangle2D;
import java.util.ArrayList;
import java.util.List;
import sitcov.world.Layout;
import sitcov.world.WorldMap;

/**
 * The strip under the world: the seed, what the map holds, a legend drawn with the map's own
 * symbols, and a scale bar with a north arrow. Drawn in pixels.
 */
final class CaptionPainter {
    private static final int SCALE_BAR_METRES = 20;
    private static final int SCALE_TICK_METRES = 10;

    private final Graphics2D g;
    private final MapStyle style;
    private final int scale;
    private final int pad;
    private final int line;

    CaptionPainter(Graphics2D g, MapStyle style) {
        this.g = g;
        this.style = style;
        this.scale = style.scale();
        this.pad = MapStyle.padding(scale);
        this.line = MapStyle.lineHeight(scale);
    }

    void paint(WorldMap map, int top, int width, int bottom) {
        g.setColor(MapStyle.CAPTION);
        g.fillRect(0, top, width, bottom - top);
        Layout layout = map.layout();

        g.setColor(MapStyle.TEXT);
        g.setFont(style.font(Font.BOLD));
        FontMetrics bold = g.getFontMetrics();
        int baseline = top + pad + bold.getAscent();
        String title = "seed " + map.seed();
        g.drawString(title, pad, baseline);
        g.setFont(style.font(Font.PLAIN));
        String note = "   200 m × 100 m, north up" + missing(layout);
        g.drawString(note, pad + bold.stringWidth(title), baseline);

        int scaleBarLeft = scaleBar(top + pad, width);
        g.setColor(MapStyle.TEXT);
        g.setFont(style.font(Font.PLAIN));
        FontMetrics plain = g.getFontMetrics();
        String counts = counts(map, false);
        if (pad + plain.stringWidth(counts) > scaleBarLeft - pad) {
            counts = counts(map, true);
        }
        if (pad + plain.stringWidth(counts) > scaleBarLeft - pad) {
            counts = counts.replaceFirst(" · \\d+ omitted$", "");
        }
        g.drawString(counts, pad, baseline + line);
        new MapLegend(g, style).paint(top + pad + 2 * line, width);
    }

    private static String missing(Layout layout) {
        List<String> absent = new ArrayList<>();
        if (layout.target().isEmpty()) {
            absent.add("no Target");
        }
        if (layout.carStart().isEmpty()) {
            absent.add("no AR start");
        }
        return absent.isEmpty() ? "" : "  —  not runnable: " + String.join(", ", absent);
    }

    /** What the map holds; {@code compact} for narrow pictures. */
    private static String counts(WorldMap map, boolean compact) {
        Layout layout = map.layout();
        int omitted = map.omissions().size();
        if (compact) {
            String text = String.format("%d roads · %d junctions (%d T, %d ends) · %d parked · %d moving",
                    layout.roads().size(), layout.junctions().size(), layout.tJunctionCount(), layout.deadEndCount(),
                    layout.parkedCars().size(), map.movingCars().size());
            return omitted == 0 ? text : text + " · " + omitted + " omitted";
        }
        String text = String.join(" · ",
                count(layout.roads().size(), "road", "roads"),
                count(layout.junctions().size(), "junction", "junctions")
                        + " (" + count(layout.tJunctionCount(), "T-junction", "T-junctions")
                        + ", " + count(layout.deadEndCount(), "dead end", "dead ends") + ")",
                count(layout.parkedCars().size(), "parked car", "parked cars"),
                count(map.movingCars().size(), "moving car", "moving cars"));
        return omitted == 0 ? text : text + " · " + count(omitted, "element", "elements") + " could not be placed";
    }

    private static String count(long n, String one, String many) {
        return n + " " + (n == 1 ? one : many);
    }

    /** A 0–10–20 m bar, right-aligned, with a north arrow to its left; returns the leftmost pixel used. */
    private int scaleBar(int rowTop, int width) {
        g.setFont(style.smallFont());
        FontMetrics fm = g.getFontMetrics();
        String unit = " m";
        int barLength = SCALE_BAR_METRES * scale;
        int right = width - pad - fm.stringWidth(unit) - fm.stringWidth(String.valueOf(SCALE_BAR_METRES)) / 2;
        int left = right - barLength;
        int barHeight = Math.max(3, line / 4);
        int barTop = rowTop + line + line / 4;
        for (int m = 0; m < SCALE_BAR_METRES; m += SCALE_TICK_METRES) {
            g.setColor((m / SCALE_TICK_METRES) % 2 == 0 ? Color.BLACK : Color.WHITE);
            g.fillRect(left + m * scale, barTop, SCALE_TICK_METRES * scale, barHeight);
        }
        g.setColor(Color.BLACK);
        g.setStroke(new BasicStroke(1f));
        g.draw(new Rectangle2D.Double(left, barTop, barLength, barHeight));
        int labelBaseline = barTop - 3;
        for (int m = 0; m <= SCALE_BAR_METRES; m += SCALE_TICK_METRES) {
            int tx = left + m * scale;
            g.draw(new Line2D.Double(tx, barTop - 2, tx, barTop + barHeight + 2));
            String label = String.valueOf(m);
            g.drawString(label, tx - fm.stringWidth(label) / 2, labelBaseline);
        }
        g.drawString(unit, right + fm.stringWidth(String.valueOf(SCALE_BAR_METRES)) / 2, labelBaseline);

        // north arrow
        int arrowX = left - 3 * pad;
        int arrowBottom = barTop + barHeight;
        int arrowTop = rowTop + fm.getAscent() + 2;
        Path2D.Double head = new Path2D.Double();
        head.moveTo(arrowX, arrowTop);
        head.lineTo(arrowX - pad * 0.7, arrowTop + pad * 1.2);
        head.lineTo(arrowX + pad * 0.7, arrowTop + pad * 1.2);
        head.closePath();
        g.fill(head);
        g.setStroke(new BasicStroke(1.5f));
        g.draw(new Line2D.Double(arrowX, arrowTop + pad, arrowX, arrowBottom));
        g.drawString("N", arrowX - fm.stringWidth("N") / 2, arrowTop - 2);
        return arrowX - Math.max(pad, fm.stringWidth("N"));
    }
}
