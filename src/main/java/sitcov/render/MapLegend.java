package sitcov.render;

import java.awt.BasicStroke;
import java.awt.FontMetrics;
import java.awt.Graphics2D;
import java.awt.geom.AffineTransform;
import java.awt.geom.Line2D;
import sitcov.geom.Box;
import sitcov.geom.Compass;
import sitcov.geom.Rect;

/**
 * The legend row of the caption: each kind of thing on the map, drawn with the map's own symbols at
 * the map's scale, and named. Narrow pictures get short names.
 */
final class MapLegend {
    private final Graphics2D g;
    private final MapStyle style;
    private final int scale;
    private final int pad;
    private final int line;

    MapLegend(Graphics2D g, MapStyle style) {
        this.g = g;
        this.style = style;
        this.scale = style.scale();
        this.pad = MapStyle.padding(scale);
        this.line = MapStyle.lineHeight(scale);
    }

    /** Draws the row whose top is {@code rowTop}, in a picture {@code width} pixels wide. */
    void paint(int rowTop, int width) {
        g.setFont(style.smallFont());
        FontMetrics fm = g.getFontMetrics();
        int x = pad;
        int mid = rowTop + line / 2;
        int baseline = mid + (fm.getAscent() - fm.getDescent()) / 2;
        String[] names = {"road, edge & centre lines", "T-junction", "dead end", "parked car", "moving car",
            "AR (autonomous car) start", "Target"};
        if (legendWidth(names, fm) > width) {
            names = new String[] {"road", "T-junction", "dead end", "parked", "moving", "AR", "Target"};
        }
        for (int i = 0; i < names.length && x < width; i++) {
            symbol(i, x, mid);
            x += symbolWidth(i) + Math.max(3, pad / 2);
            g.setColor(MapStyle.TEXT);
            g.setFont(style.smallFont());
            g.drawString(names[i], x, baseline);
            x += fm.stringWidth(names[i]) + 2 * pad;
        }
    }

    private int legendWidth(String[] names, FontMetrics fm) {
        int total = pad;
        for (int i = 0; i < names.length; i++) {
            total += symbolWidth(i) + Math.max(3, pad / 2) + fm.stringWidth(names[i]) + 2 * pad;
        }
        return total;
    }

    private int symbolHeight() {
        return Math.max(6, (int) (line * 0.8));
    }

    private int symbolWidth(int i) {
        int h = symbolHeight();
        return switch (i) {
            case 0 -> 3 * h;
            case 3, 4 -> (int) Math.ceil(5.0 * scale);
            case 5 -> (int) Math.ceil((2 + MapShapes.AR_ARROW_AHEAD) * scale) + 1;
            default -> h;
        };
    }

    /** Draws legend symbol {@code i} starting at {@code x}, centred on {@code mid}. */
    private void symbol(int i, int x, int mid) {
        int h = symbolHeight();
        switch (i) {
            case 0 -> {
                int w = 3 * h;
                g.setColor(MapStyle.ASPHALT);
                g.fillRect(x, mid - h / 2, w, h);
                g.setStroke(new BasicStroke(1.5f));
                g.setColor(MapStyle.EDGE_LINE);
                g.draw(new Line2D.Double(x, mid - h / 2.0 + 2, x + w, mid - h / 2.0 + 2));
                g.draw(new Line2D.Double(x, mid + h / 2.0 - 2, x + w, mid + h / 2.0 - 2));
                g.setColor(MapStyle.CENTRE_LINE);
                float dash = Math.max(2f, 2f * scale);
                g.setStroke(new BasicStroke(1.5f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10f,
                        new float[] {dash, dash / 2}, 0f));
                g.draw(new Line2D.Double(x, mid, x + w, mid));
            }
            case 1, 2 -> {
                g.setColor(i == 1 ? MapStyle.T_JUNCTION : MapStyle.DEAD_END);
                g.fillRect(x, mid - h / 2, h, h);
                if (i == 2) {
                    inMetres(x, mid - h / 2, () -> new MapShapes(g, style).barrier(
                            new Rect(0, 0, (double) h / scale, (double) h / scale), Compass.EAST,
                            style.atLeastPixels(0.6, 3)));
                }
            }
            case 3, 4 -> {
                double len = 5;
                inMetres(x, mid, () -> {
                    MapShapes shapes = new MapShapes(g, style);
                    if (i == 3) {
                        shapes.box(Box.centred(len / 2, 0, 90, len, 2), MapStyle.PARKED_CAR, MapStyle.PARKED_OUTLINE, 1.2);
                    } else {
                        shapes.movingCar(Box.behind(len, 0, 90, len, 2), len, 0, 90);
                    }
                });
            }
            case 5 -> {
                inMetres(x, mid, () -> new MapShapes(g, style).autonomousCar(Box.behind(2, 0, 90, 2, 2), 2, 0, 90));
            }
            default -> {
                double radius = h / 2.0 / scale;
                inMetres(x, mid, () -> new MapShapes(g, style).target(radius, 0, radius));
            }
        }
    }

    /** Runs {@code draw} with user space in metres, its origin at pixel ({@code x}, {@code y}). */
    private void inMetres(double x, double y, Runnable draw) {
        AffineTransform saved = g.getTransform();
        g.translate(x, y);
        g.scale(scale, scale);
        draw.run();
        g.setTransform(saved);
    }

}
