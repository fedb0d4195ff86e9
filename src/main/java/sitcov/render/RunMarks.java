package sitcov.render;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.Shape;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Line2D;
import java.awt.geom.Path2D;
import java.awt.geom.Rectangle2D;
import sitcov.geom.Box;
import sitcov.oracle.AccidentType;
import sitcov.world.Dimensions;
import sitcov.world.StartPose;
import sitcov.world.WorldMap;

/**
 * What {@link RunRenderer} draws over a map: the car's path coloured by what it was doing, its
 * footprints, and one marker per kind of accident. Paths and footprints are drawn in metres,
 * markers in pixels.
 */
final class RunMarks {
    static final Color DRIVING = new Color(0x00E5FF);
    static final Color CROSSING = new Color(0xFF9F1C);
    static final Color OVERTAKING = new Color(0xFF4FD8);
    static final Color PATH_SHADOW = new Color(0, 0, 0, 150);
    static final Color FOOTPRINT = new Color(255, 255, 255, 150);
    static final Color FINAL_FILL = new Color(255, 255, 255, 200);
    /** A closest approach's dot (see {@link RunRenderer}): a green no path, marker or map colour uses. */
    static final Color CLOSEST = new Color(0x39E639);
    /** Its label's accent, darker so that it shows on the label's light background. */
    static final Color CLOSEST_ACCENT = new Color(0x1B8A1B);
    /** Metres of path between two direction arrowheads. */
    static final double CHEVRON_SPACING = 15;

    private final Graphics2D g;
    private final MapStyle style;

    RunMarks(Graphics2D g, MapStyle style) {
        this.g = g;
        this.style = style;
    }

    static Color colour(TrajectoryRecorder t, int i) {
        return t.crossing(i) ? CROSSING : t.overtaking(i) ? OVERTAKING : DRIVING;
    }

    static Box body(double x, double y, double heading) {
        return Box.behind(x, y, heading, Dimensions.AUTONOMOUS_CAR_LENGTH, Dimensions.AUTONOMOUS_CAR_WIDTH);
    }

    /** The path of the front centre from the start pose, one colour run per state (metres). */
    void path(WorldMap map, TrajectoryRecorder t, double pixels) {
        path(map, t, pixels, t.ticks());
    }

    /** The path as far as its first {@code entries} entries: the path driven so far, in an animation. */
    void path(WorldMap map, TrajectoryRecorder t, double pixels, int entries) {
        int n = Math.min(entries, t.ticks());
        if (n <= 0) {
            return;
        }
        StartPose start = map.layout().carStart().orElse(null);
        double px = start != null ? start.position().x() : t.x(0);
        double py = start != null ? start.position().y() : t.y(0);
        BasicStroke shadow = new BasicStroke((float) ((pixels + 2) / style.scale()), BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND);
        BasicStroke line = new BasicStroke((float) (pixels / style.scale()), BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND);
        for (int pass = 0; pass < 2; pass++) {
            double x = px;
            double y = py;
            int i = 0;
            while (i < n) {
                Color c = colour(t, i);
                Path2D.Double run = new Path2D.Double();
                run.moveTo(x, y);
                while (i < n && colour(t, i).equals(c)) {
                    x = t.x(i);
                    y = t.y(i);
                    run.lineTo(x, y);
                    i++;
                }
                g.setColor(pass == 0 ? PATH_SHADOW : c);
                g.setStroke(pass == 0 ? shadow : line);
                g.draw(run);
            }
        }
        chevrons(t, pixels, n);
    }

    /** Notched arrowheads every {@link #CHEVRON_SPACING} metres of path, pointing the way the car went. */
    private void chevrons(TrajectoryRecorder t, double pixels, int entries) {
        double size = Math.max(0.9, 2.5 * pixels / style.scale());
        double travelled = CHEVRON_SPACING / 2;
        g.setStroke(style.pixelStroke(1));
        for (int i = 1; i < entries; i++) {
            travelled += Math.hypot(t.x(i) - t.x(i - 1), t.y(i) - t.y(i - 1));
            if (travelled < CHEVRON_SPACING) {
                continue;
            }
            int j = i - 1; // the direction over the last metre or so, not one zig-zagging tick
            while (j > 0 && i - j < 50 && Math.hypot(t.x(i) - t.x(j), t.y(i) - t.y(j)) < 1) {
                j--;
            }
            if (Math.hypot(t.x(i) - t.x(j), t.y(i) - t.y(j)) < 0.05) {
                continue;
            }
            travelled = 0;
            double fx = t.x(i) - t.x(j);
            double fy = t.y(i) - t.y(j);
            double n = Math.hypot(fx, fy);
            fx /= n;
            fy /= n;
            double len = size;
            double half = size * 0.42;
            Path2D.Double head = new Path2D.Double();
            head.moveTo(t.x(i) + fx * len * 0.6, t.y(i) + fy * len * 0.6);
            head.lineTo(t.x(i) - fx * len * 0.4 + fy * half, t.y(i) - fy * len * 0.4 - fx * half);
            head.lineTo(t.x(i) - fx * len * 0.15, t.y(i) - fy * len * 0.15);
            head.lineTo(t.x(i) - fx * len * 0.4 - fy * half, t.y(i) - fy * len * 0.4 + fx * half);
            head.closePath();
            g.setColor(colour(t, i));
            g.fill(head);
            g.setColor(Color.BLACK);
            g.draw(head);
        }
    }

    /** Faint footprint outlines every {@code every} ticks, coloured ones if {@code coloured} (metres). */
    void footprints(TrajectoryRecorder t, int every, boolean coloured) {
        g.setStroke(style.pixelStroke(1));
        for (int i = 0; i < t.ticks(); i += every) {
            Color c = coloured ? colour(t, i) : FOOTPRINT;
            g.setColor(new Color(c.getRed(), c.getGreen(), c.getBlue(), coloured ? 110 : FOOTPRINT.getAlpha()));
            g.draw(MapShapes.polygon(body(t.x(i), t.y(i), t.heading(i))));
        }
    }

    /** The car's footprint at the last tick, solid (metres). */
    void finalFootprint(TrajectoryRecorder t) {
        int last = t.ticks() - 1;
        if (last >= 0) {
            new MapShapes(g, style).box(body(t.x(last), t.y(last), t.heading(last)), FINAL_FILL, Color.BLACK, 2);
        }
    }

    static Color markerColour(AccidentType type) {
        return switch (type) {
            case LEAVEROAD -> new Color(0xE50914);
            case CROSSCENTRELINE -> new Color(0xFFE600);
            case CLASHWITHOBSTACLE -> Color.WHITE;
            case CLASHWITHOTHERCAR -> new Color(0xB84FD0);
            case TIMEOUT -> Color.BLACK;
        };
    }

    /** A marker of radius {@code r} pixels centred on pixel ({@code x}, {@code y}): its own shape per type. */
    void marker(AccidentType type, double x, double y, double r) {
        Shape shape = switch (type) {
            case LEAVEROAD -> polygon(x, y, r * 1.15, 3, -90);
            case CROSSCENTRELINE -> polygon(x, y, r * 1.1, 4, -90);
            case CLASHWITHOBSTACLE -> new Rectangle2D.Double(x - r * 0.85, y - r * 0.85, r * 1.7, r * 1.7);
            case CLASHWITHOTHERCAR -> star(x, y, r * 1.2);
            case TIMEOUT -> new Ellipse2D.Double(x - r, y - r, 2 * r, 2 * r);
        };
        g.setStroke(new BasicStroke(4f, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
        g.setColor(Color.WHITE);
        g.draw(shape);
        if (type == AccidentType.TIMEOUT) { // a clock face, hollow so the car it marks stays visible
            g.setStroke(new BasicStroke(2.5f));
            g.setColor(Color.BLACK);
            g.draw(shape);
            g.setStroke(new BasicStroke(1.5f, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
            g.draw(new Line2D.Double(x, y, x, y - r * 0.7));
            g.draw(new Line2D.Double(x, y, x + r * 0.5, y));
            return;
        }
        g.setColor(markerColour(type));
        g.fill(shape);
        g.setStroke(new BasicStroke(1.5f, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
        g.setColor(Color.BLACK);
        g.draw(shape);
        if (type == AccidentType.CLASHWITHOBSTACLE) {
            double a = r * 0.5;
            g.draw(new Line2D.Double(x - a, y - a, x + a, y + a));
            g.draw(new Line2D.Double(x - a, y + a, x + a, y - a));
        }
    }

    /** A closest approach: a small green dot, outlined black and white so it shows on the path and the road. */
    static void closestDot(Graphics2D g, double x, double y, double r) {
        Ellipse2D dot = new Ellipse2D.Double(x - r, y - r, 2 * r, 2 * r);
        g.setStroke(new BasicStroke(3.5f));
        g.setColor(Color.WHITE);
        g.draw(dot);
        g.setColor(CLOSEST);
        g.fill(dot);
        g.setStroke(new BasicStroke(1.5f));
        g.setColor(Color.BLACK);
        g.draw(dot);
    }

    private static Path2D polygon(double x, double y, double r, int corners, double startDegrees) {
        Path2D.Double p = new Path2D.Double();
        for (int k = 0; k < corners; k++) {
            double a = Math.toRadians(startDegrees + 360.0 * k / corners);
            double px = x + r * Math.cos(a);
            double py = y + r * Math.sin(a) + (corners == 3 ? r * 0.2 : 0);
            if (k == 0) {
                p.moveTo(px, py);
            } else {
                p.lineTo(px, py);
            }
        }
        p.closePath();
        return p;
    }

    private static Path2D star(double x, double y, double r) {
        Path2D.Double p = new Path2D.Double();
        for (int k = 0; k < 10; k++) {
            double a = Math.toRadians(-90 + 36 * k);
            double d = k % 2 == 0 ? r : r * 0.45;
            if (k == 0) {
                p.moveTo(x + d * Math.cos(a), y + d * Math.sin(a));
            } else {
                p.lineTo(x + d * Math.cos(a), y + d * Math.sin(a));
            }
        }
        p.closePath();
        return p;
    }
}
