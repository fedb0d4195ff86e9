package sitcov.render;

import java.awt.Color;
import java.awt.Font;
import java.awt.FontMetrics;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.geom.AffineTransform;
import java.awt.geom.Point2D;
import java.awt.geom.Rectangle2D;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.stream.Collectors;
import sitcov.oracle.Accident;
import sitcov.oracle.NearMiss;
import sitcov.oracle.NearMisses;
import sitcov.oracle.RunResult;
import sitcov.world.Dimensions;
import sitcov.world.WorldMap;

/**
 * Draws one run over its map: the car's path (coloured by driving, crossing a junction,
 * overtaking), its footprint every few ticks and at the end, and a labelled marker at each
 * accident, a small dot where the run came closest to a moving car, a parked car, the road's edge
 * and the centre line; the caption gives the seeds, the outcome, the accidents and the least ρ. A zoomed window around a
 * point shows a manoeuvre closely, with the footprint of every tick.
 */
public final class RunRenderer {
    /** Accidents drawn closer than this many pixels to an earlier one share its label. */
    private static final double SAME_PLACE_PIXELS = 18;
    private static final int MAX_PER_LABEL = 3;

    private final int scale;

    public RunRenderer(int pixelsPerMetre) {
        this.scale = new MapRenderer(pixelsPerMetre).pixelsPerMetre();
    }

    /** A ring round a point of the run (metres), labelled: where a fault first acted, say. */
    public record Ring(double x, double y, Color colour, String label) {
    }

    /**
     * What {@link #render} adds to a plain run: rings, and one accident singled out, its marker
     * ringed in {@code colour} and its label starting with {@code prefix}.
     */
    public record Highlights(List<Ring> rings, Optional<Accident> accident, Color colour, String prefix) {
        public static final Highlights NONE = new Highlights(List.of(), Optional.empty(), Color.BLACK, "");

        public Highlights {
            rings = List.copyOf(rings);
        }
    }

    /** A drawn run and the tags its labels took, in pixels. */
    record Picture(BufferedImage image, List<Rectangle2D> labels) {
    }

    /** The whole map at this renderer's scale, {@link MapRenderer#imageSize} big, with the run on it. */
    public BufferedImage render(WorldMap map, TrajectoryRecorder trajectory, RunResult result) {
        return render(map, trajectory, result, Highlights.NONE);
    }

    /** The run as {@link #render(WorldMap, TrajectoryRecorder, RunResult)} draws it, with {@code highlights}. */
    public BufferedImage render(WorldMap map, TrajectoryRecorder trajectory, RunResult result, Highlights highlights) {
        return draw(map, trajectory, result, highlights).image();
    }

    /**
     * Every label of the picture (the map's, the accidents', the rings') goes through one
     * {@link LabelPlacer}, so none is drawn over another.
     */
    Picture draw(WorldMap map, TrajectoryRecorder trajectory, RunResult result, Highlights highlights) {
        MapStyle style = new MapStyle(scale);
        List<Rectangle2D> placed = new ArrayList<>();
        int worldHeight = MapRenderer.worldHeightPixels(scale);
        AffineTransform world = AffineTransform.getScaleInstance(scale, scale);
        Rectangle2D worldArea = new Rectangle2D.Double(0, 0, MapRenderer.imageSize(scale).width, worldHeight);
        BufferedImage image = new MapRenderer(scale).render(map, new MapRenderer.Overlay() {
            @Override
            public void drawInWorld(Graphics2D metres) {
                drawRun(metres, style, new AffineTransform(), map, trajectory, 10, false, 2.5);
            }

            @Override
            public void drawLabelled(Graphics2D pixels, LabelPlacer labels) {
                double r = ringRadius(style);
                for (Ring ring : highlights.rings()) {
                    Point2D p = world.transform(new Point2D.Double(ring.x(), ring.y()), null);
                    ring(pixels, p, r, ring.colour());
                    labels.reserve(new Rectangle2D.Double(p.getX() - r, p.getY() - r, 2 * r, 2 * r));
                }
                List<Closest> closest = closest(trajectory, result);
                double dot = closestRadius(style);
                for (Closest c : closest) {
                    Point2D p = world.transform(new Point2D.Double(c.x(), c.y()), null);
                    labels.reserve(new Rectangle2D.Double(p.getX() - dot, p.getY() - dot, 2 * dot, 2 * dot));
                }
                accidents(pixels, style, labels, world, result.accidents(), worldArea, true, highlights);
                for (Ring ring : highlights.rings()) {
                    Point2D p = world.transform(new Point2D.Double(ring.x(), ring.y()), null);
                    labels.place(ring.label(), p.getX(), p.getY(), r + 3, r + 1, ring.colour());
                }
                closestApproaches(pixels, labels, world, closest, dot);
                placed.addAll(labels.placed());
            }
        });
        Graphics2D g = graphics(image);
        try {
            new RunCaption(g, style).paint(result, worldHeight + Math.max(1, scale / 3), image.getWidth(), image.getHeight());
        } finally {
            g.dispose();
        }
        return new Picture(image, List.copyOf(placed));
    }

    /**
     * Where the run came closest to a moving car, a parked car, the road's edge and the centre line:
     * the middle of the car's footprint at the tick each least gap or margin was first reached. A
     * margin below zero that the run's accident of that type already marks is left to its marker.
     */
    record Closest(NearMiss measure, double value, long tick, double x, double y) {
        String text() {
            return NearMissText.shortName(measure) + " " + NearMissText.value(measure, value, 2) + " t=" + tick;
        }
    }

    static List<Closest> closest(TrajectoryRecorder trajectory, RunResult result) {
        List<Closest> all = new ArrayList<>();
        if (trajectory.nearMisses().isEmpty()) {
            return all;
        }
        NearMisses watched = trajectory.nearMisses().get();
        for (NearMiss m : CLOSEST) {
            double v = watched.least(m);
            if (!Double.isFinite(v) || (v < 0 && result.countsByType().getOrDefault(NearMissText.accident(m), 0L) > 0)) {
                continue;
            }
            int i = trajectory.entryOf(watched.tickOf(m));
            var middle = RunMarks.body(trajectory.x(i), trajectory.y(i), trajectory.heading(i)).centre();
            all.add(new Closest(m, v, watched.tickOf(m), middle.x(), middle.y()));
        }
        return all;
    }

    /** The measures in metres a picture marks; the two times have no one place. */
    private static final List<NearMiss> CLOSEST = List.of(NearMiss.MOVING_GAP, NearMiss.PARKED_GAP,
            NearMiss.ROAD_EDGE, NearMiss.CENTRE_LINE);

    private static double closestRadius(MapStyle style) {
        return Math.max(4, 0.7 * style.scale());
    }

    /** A small dot at each closest approach, labelled last, those at about the same place sharing a label. */
    /** Puts {@code item}, drawn at {@code p}, in the group of marks drawn at about the same place, or a new one. */
    private static <T> void samePlace(List<Point2D> anchors, List<List<T>> groups, Point2D p, T item) {
        for (int k = 0; k < groups.size(); k++) {
            if (anchors.get(k).distance(p) < SAME_PLACE_PIXELS) {
                groups.get(k).add(item);
                return;
            }
        }
        anchors.add(p);
        groups.add(new ArrayList<>(List.of(item)));
    }

    private static void closestApproaches(Graphics2D g, LabelPlacer labels, AffineTransform world, List<Closest> closest,
                                          double r) {
        List<Point2D> anchors = new ArrayList<>();
        List<List<Closest>> groups = new ArrayList<>();
        for (Closest c : closest) {
            Point2D p = world.transform(new Point2D.Double(c.x(), c.y()), null);
            RunMarks.closestDot(g, p.getX(), p.getY(), r);
            samePlace(anchors, groups, p, c);
        }
        for (int k = 0; k < groups.size(); k++) {
            String text = "closest: " + groups.get(k).stream().map(Closest::text).collect(Collectors.joining(", "));
            labels.place(text, anchors.get(k).getX(), anchors.get(k).getY(), r + 3, r + 1, RunMarks.CLOSEST_ACCENT);
        }
    }

    /** Radius in pixels of a ring round a point of the run: wider than an accident marker, so both show. */
    private static double ringRadius(MapStyle style) {
        return Math.max(10, 3 * style.scale());
    }

    private static void ring(Graphics2D g, Point2D p, double r, Color colour) {
        g.setStroke(new java.awt.BasicStroke(3f));
        g.setColor(colour);
        g.draw(new java.awt.geom.Ellipse2D.Double(p.getX() - r, p.getY() - r, 2 * r, 2 * r));
    }

    /**
     * A square window {@code 2 * radiusMetres} wide around ({@code centreX}, {@code centreY}) at
     * {@code pixelsPerMetre}, with the car's footprint at every tick and the ticks written along its path.
     */
    public BufferedImage renderWindow(WorldMap map, TrajectoryRecorder trajectory, RunResult result,
                                      double centreX, double centreY, double radiusMetres, int pixelsPerMetre) {
        MapRenderer mapRenderer = new MapRenderer(pixelsPerMetre);
        if (!(radiusMetres > 0) || 2 * radiusMetres * pixelsPerMetre > 10_000) {
            throw new IllegalArgumentException("a window needs a radius above 0 and at most 10 000 pixels across");
        }
        int size = (int) Math.round(2 * radiusMetres * pixelsPerMetre);
        BufferedImage image = new BufferedImage(size, size, BufferedImage.TYPE_INT_RGB);
        MapStyle style = new MapStyle(pixelsPerMetre);
        MapStyle textStyle = new MapStyle(Math.min(pixelsPerMetre, MapRenderer.DEFAULT_SCALE));
        AffineTransform world = AffineTransform.getScaleInstance(pixelsPerMetre, pixelsPerMetre);
        world.translate(radiusMetres - centreX, radiusMetres - centreY);
        Graphics2D g = graphics(image);
        try {
            g.setColor(MapStyle.FRAME);
            g.fillRect(0, 0, size, size);
            AffineTransform pixels = g.getTransform();
            g.transform(world);
            mapRenderer.drawWorld(g, map);
            g.setTransform(pixels);
            drawRun(g, style, world, map, trajectory, 1, true, 3);
            tickNumbers(g, textStyle, world, trajectory, size);
            LabelPlacer labels = new LabelPlacer(g, textStyle, new Rectangle2D.Double(0, 0, size, size));
            accidents(g, textStyle, labels, world, result.accidents(), new Rectangle2D.Double(0, 0, size, size), false,
                    Highlights.NONE);
            g.setFont(textStyle.font(Font.BOLD));
            FontMetrics fm = g.getFontMetrics();
            String title = String.format(Locale.ROOT, "seed %d / %d · around (%.1f, %.1f) · %d px/m · grid 10 m",
                    result.externalSeed(), result.internalSeed(), centreX, centreY, pixelsPerMetre);
            if (fm.stringWidth(title) + 8 > size) {
                title = String.format(Locale.ROOT, "seed %d/%d · (%.1f, %.1f)", result.externalSeed(),
                        result.internalSeed(), centreX, centreY);
            }
            g.setColor(MapStyle.LABEL_BACKGROUND);
            g.fillRect(0, 0, fm.stringWidth(title) + 8, fm.getHeight() + 4);
            g.setColor(MapStyle.TEXT);
            g.drawString(title, 4, 2 + fm.getAscent());
        } finally {
            g.dispose();
        }
        return image;
    }

    /** Writes the picture atomically: to a temporary file in the same folder, then moved into place. */
    public void writePng(BufferedImage image, Path file) throws IOException {
        MapRenderer.writeAtomically(image, file);
    }

    private static Graphics2D graphics(BufferedImage image) {
        Graphics2D g = image.createGraphics();
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
        g.setRenderingHint(RenderingHints.KEY_STROKE_CONTROL, RenderingHints.VALUE_STROKE_PURE);
        g.setRenderingHint(RenderingHints.KEY_RENDERING, RenderingHints.VALUE_RENDER_QUALITY);
        return g;
    }

    /** Footprints, then the path over them, then the final footprint, in world coordinates. */
    private static void drawRun(Graphics2D g, MapStyle style, AffineTransform world, WorldMap map,
                                TrajectoryRecorder t, int every, boolean coloured, double pathPixels) {
        AffineTransform pixels = g.getTransform();
        g.transform(world);
        RunMarks marks = new RunMarks(g, style);
        marks.footprints(t, every, coloured);
        marks.path(map, t, pathPixels);
        marks.finalFootprint(t);
        g.setTransform(pixels);
    }

    /**
     * A marker at each accident, then their labels, accidents at about the same place sharing one.
     * Accidents outside {@code area} are pinned to its edge and say where they were ({@code pin}),
     * or left out.
     */
    private static void accidents(Graphics2D g, MapStyle style, LabelPlacer labels, AffineTransform world,
                                  List<Accident> accidents, Rectangle2D area, boolean pin, Highlights highlights) {
        double r = Math.max(7, 0.6 * style.scale());
        List<Point2D> anchors = new ArrayList<>();
        List<List<Accident>> groups = new ArrayList<>();
        List<Accident> shown = new ArrayList<>();
        List<Point2D> at = new ArrayList<>();
        for (Accident a : accidents) {
            Point2D p = world.transform(new Point2D.Double(a.x(), a.y()), null);
            if (!area.contains(p) && !pin) {
                continue;
            }
            if (pin) {
                p = new Point2D.Double(Math.max(area.getMinX() + r + 2, Math.min(p.getX(), area.getMaxX() - r - 2)),
                        Math.max(area.getMinY() + r + 2, Math.min(p.getY(), area.getMaxY() - r - 2)));
            }
            shown.add(a);
            at.add(p);
            labels.reserve(new Rectangle2D.Double(p.getX() - r, p.getY() - r, 2 * r, 2 * r));
            samePlace(anchors, groups, p, a);
        }
        for (int i = shown.size() - 1; i >= 0; i--) { // the first accident on top
            new RunMarks(g, style).marker(shown.get(i).type(), at.get(i).getX(), at.get(i).getY(), r);
        }
        for (int i = 0; i < shown.size(); i++) {
            if (highlights.accident().filter(shown.get(i)::equals).isPresent()) {
                ring(g, at.get(i), ringRadius(style), highlights.colour());
            }
        }
        for (int k = 0; k < groups.size(); k++) {
            List<Accident> group = groups.get(k);
            boolean singled = highlights.accident().filter(group::contains).isPresent();
            String text = (singled ? highlights.prefix() : "") + group.stream().limit(MAX_PER_LABEL).map(a -> a.type() + " t=" + a.tick() + offMap(a))
                    .collect(Collectors.joining(", "))
                    + (group.size() > MAX_PER_LABEL ? " +" + (group.size() - MAX_PER_LABEL) + " more" : "");
            Color accent = singled ? highlights.colour() : RunMarks.markerColour(group.get(0).type());
            labels.place(text, anchors.get(k).getX(), anchors.get(k).getY(), r + 3, r + 1,
                    accent.equals(Color.WHITE) ? Color.BLACK : accent);
        }
    }

    /** Where an accident off the world happened, for its label. */
    private static String offMap(Accident a) {
        boolean inside = a.x() >= 0 && a.x() <= Dimensions.WORLD_WIDTH && a.y() >= 0 && a.y() <= Dimensions.WORLD_HEIGHT;
        return inside ? "" : String.format(Locale.ROOT, " off the map at (%.0f, %.0f)", a.x(), a.y());
    }

    /** Small tick numbers along the path, where the car moved at least 1.5 m since the last one. */
    private static void tickNumbers(Graphics2D g, MapStyle style, AffineTransform world, TrajectoryRecorder t, int size) {
        g.setFont(style.smallFont());
        FontMetrics fm = g.getFontMetrics();
        double lastX = Double.NaN;
        double lastY = Double.NaN;
        for (int i = 0; i < t.ticks(); i++) {
            if (!Double.isNaN(lastX) && Math.hypot(t.x(i) - lastX, t.y(i) - lastY) < 1.5) {
                continue;
            }
            Point2D p = world.transform(new Point2D.Double(t.x(i), t.y(i)), null);
            if (p.getX() < 0 || p.getY() < 0 || p.getX() >= size || p.getY() >= size) {
                continue;
            }
            lastX = t.x(i);
            lastY = t.y(i);
            String text = String.valueOf(t.tick(i));
            double x = p.getX() + 4;
            double y = p.getY() - 4;
            g.setColor(new Color(255, 255, 255, 190));
            g.fill(new Rectangle2D.Double(x - 1, y - fm.getAscent(), fm.stringWidth(text) + 2, fm.getAscent() + 1));
            g.setColor(MapStyle.TEXT);
            g.drawString(text, (float) x, (float) y);
        }
    }
}
