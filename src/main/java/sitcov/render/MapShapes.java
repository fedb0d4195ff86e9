package sitcov.render;

import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Path2D;
import java.awt.geom.Rectangle2D;
import sitcov.geom.Bearing;
import sitcov.geom.Box;
import sitcov.geom.Compass;
import sitcov.geom.Rect;

/**
 * The map's symbols, drawn on a graphics whose user space is metres (so the legend can draw the
 * very same symbols as the map, just somewhere else).
 */
public final class MapShapes {
    /** How far the autonomous car's heading arrow reaches past its front, in metres. */
    static final double AR_ARROW_AHEAD = 2.6;

    private final Graphics2D g;
    private final MapStyle style;

    MapShapes(Graphics2D g, MapStyle style) {
        this.g = g;
        this.style = style;
    }

    public static Path2D polygon(Box box) {
        double[] c = box.corners();
        Path2D.Double p = new Path2D.Double();
        p.moveTo(c[0], c[1]);
        for (int i = 2; i < c.length; i += 2) {
            p.lineTo(c[i], c[i + 1]);
        }
        p.closePath();
        return p;
    }

    static Rectangle2D rectangle(Rect r) {
        return new Rectangle2D.Double(r.minX(), r.minY(), r.width(), r.height());
    }

    /** A filled box with an outline at least {@code outlinePixels} wide. */
    void box(Box box, Color fill, Color outline, double outlinePixels) {
        Path2D shape = polygon(box);
        g.setColor(fill);
        g.fill(shape);
        g.setColor(outline);
        g.setStroke(style.pixelStroke(outlinePixels));
        g.draw(shape);
    }

    /**
     * A triangle pointing along {@code bearing}: its tip {@code ahead} metres in front of
     * ({@code x}, {@code y}), its base {@code behind} metres behind it, {@code halfWidth} to each side.
     */
    static Path2D arrowHead(double x, double y, double bearing, double ahead, double behind, double halfWidth) {
        double fx = Bearing.dx(bearing);
        double fy = Bearing.dy(bearing);
        double sx = fy;
        double sy = -fx;
        Path2D.Double p = new Path2D.Double();
        p.moveTo(x + fx * ahead, y + fy * ahead);
        p.lineTo(x - fx * behind + sx * halfWidth, y - fy * behind + sy * halfWidth);
        p.lineTo(x - fx * behind - sx * halfWidth, y - fy * behind - sy * halfWidth);
        p.closePath();
        return p;
    }

    /** A moving car: its body, and a white chevron inside its front showing where it faces. */
    void movingCar(Box body, double frontX, double frontY, double bearing) {
        box(body, MapStyle.MOVING_CAR, MapStyle.MOVING_OUTLINE, 1.2);
        g.setColor(Color.WHITE);
        g.fill(arrowHead(frontX, frontY, bearing, -0.3, 1.9, 0.7));
    }

    /** The autonomous car: a bright box and an arrow ahead of its front. */
    void autonomousCar(Box body, double frontX, double frontY, double bearing) {
        Path2D arrow = arrowHead(frontX, frontY, bearing, AR_ARROW_AHEAD, -0.2, 1.1);
        g.setColor(MapStyle.AUTONOMOUS_CAR);
        g.fill(arrow);
        g.setColor(MapStyle.AUTONOMOUS_OUTLINE);
        g.setStroke(style.pixelStroke(1.5));
        g.draw(arrow);
        box(body, MapStyle.AUTONOMOUS_CAR, MapStyle.AUTONOMOUS_OUTLINE, 1.8);
    }

    /** The Target: a red and white bullseye of {@link MapStyle#TARGET_RADIUS}. */
    void target(double x, double y, double radius) {
        double[] radii = {radius, radius * 2 / 3, radius / 3};
        Color[] colours = {MapStyle.TARGET, MapStyle.TARGET_RING, MapStyle.TARGET};
        for (int i = 0; i < radii.length; i++) {
            g.setColor(colours[i]);
            g.fill(circle(x, y, radii[i]));
        }
        g.setColor(Color.BLACK);
        g.setStroke(style.pixelStroke(1.2));
        g.draw(circle(x, y, radius));
    }

    private static Ellipse2D circle(double x, double y, double r) {
        return new Ellipse2D.Double(x - r, y - r, 2 * r, 2 * r);
    }

    /**
     * A dead end's barrier: a red and white striped band along the side of the square facing away
     * from its only arm, where the road stops.
     */
    void barrier(Rect square, Compass closedSide, double thickness) {
        boolean across = closedSide.isNorthSouth(); // the band runs east–west
        double length = across ? square.width() : square.height();
        int stripes = Math.max(2, (int) Math.round(length));
        double step = length / stripes;
        for (int i = 0; i < stripes; i++) {
            double bx;
            double by;
            double bw;
            double bh;
            if (across) {
                bx = square.minX() + i * step;
                by = closedSide == Compass.NORTH ? square.minY() : square.maxY() - thickness;
                bw = step;
                bh = thickness;
            } else {
                bx = closedSide == Compass.WEST ? square.minX() : square.maxX() - thickness;
                by = square.minY() + i * step;
                bw = thickness;
                bh = step;
            }
            g.setColor(i % 2 == 0 ? MapStyle.BARRIER_A : MapStyle.BARRIER_B);
            g.fill(new Rectangle2D.Double(bx, by, bw, bh));
        }
    }
}
