package sitcov.render;

import java.awt.BasicStroke;
import java.awt.Dimension;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.geom.AffineTransform;
import java.awt.geom.Line2D;
import java.awt.geom.Rectangle2D;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import sitcov.geom.Box;
import sitcov.geom.Rect;
import sitcov.results.IoReason;
import sitcov.results.OutputFile;
import sitcov.world.Dimensions;
import sitcov.world.Junction;
import sitcov.world.Layout;
import sitcov.world.Marking;
import sitcov.world.MarkingKind;
import sitcov.world.ParkedCar;
import sitcov.world.RoadNetwork;
import sitcov.world.StartPose;
import sitcov.world.Target;
import sitcov.world.WorldMap;

/**
 * Draws a map as a PNG, headless: grass, roads, junction squares (dead ends barred), the painted
 * lines, parked cars, the Target, the autonomous car and the moving cars at their starts, and a
 * caption strip below the world with the seed, the counts, a legend and a scale bar. North is up;
 * a metre is {@code pixelsPerMetre} pixels.
 */
public final class MapRenderer {
    public static final int DEFAULT_SCALE = 6; // pixels per metre
    /** The largest scale accepted: a 200 m world is then 10 000 pixels wide. */
    public static final int MAX_SCALE = 50;

    private final int scale;
    private final MapStyle style;

    public MapRenderer() {
        this(DEFAULT_SCALE);
    }

    public MapRenderer(int pixelsPerMetre) {
        checkScale(pixelsPerMetre);
        this.scale = pixelsPerMetre;
        this.style = new MapStyle(pixelsPerMetre);
    }

    /** Image size for a given scale: the world area plus a caption strip below it. */
    public static Dimension imageSize(int pixelsPerMetre) {
        checkScale(pixelsPerMetre);
        int width = (int) Math.round(Dimensions.WORLD_WIDTH * pixelsPerMetre);
        int height = (int) Math.round(Dimensions.WORLD_HEIGHT * pixelsPerMetre) + MapStyle.captionHeight(pixelsPerMetre);
        return new Dimension(width, height);
    }

    public int pixelsPerMetre() {
        return scale;
    }

    /**
     * What a picture drawn over the map adds (a run, say): things drawn in the world under the
     * map's labels, and labelled marks drawn after them, whose labels keep clear of the map's.
     */
    interface Overlay {
        Overlay NONE = new Overlay() { };

        /** Draws on {@code metres}, whose user space is the world in metres, over the world and under every label. */
        default void drawInWorld(Graphics2D metres) {
        }

        /** Draws on {@code pixels} once the map's labels are placed; {@code labels} keeps new labels off them. */
        default void drawLabelled(Graphics2D pixels, LabelPlacer labels) {
        }
    }

    public BufferedImage render(WorldMap map) {
        return render(map, Overlay.NONE);
    }

    /**
     * The map without its moving cars at their starts, for pictures that draw them where they are
     * (an animation, the viewer); the caption still counts them, as {@link #render(WorldMap)}'s does.
     */
    public BufferedImage renderWithoutTraffic(WorldMap map) {
        return render(map, Overlay.NONE, false);
    }

    /** The map with {@code overlay} drawn over it (the caption is still the map's). */
    BufferedImage render(WorldMap map, Overlay overlay) {
        return render(map, overlay, true);
    }

    private BufferedImage render(WorldMap map, Overlay overlay, boolean traffic) {
        Dimension size = imageSize(scale);
        int worldHeight = worldHeightPixels(scale);
        BufferedImage image = new BufferedImage(size.width, size.height, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = image.createGraphics();
        try {
            g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
            g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
            g.setRenderingHint(RenderingHints.KEY_STROKE_CONTROL, RenderingHints.VALUE_STROKE_PURE);
            g.setRenderingHint(RenderingHints.KEY_RENDERING, RenderingHints.VALUE_RENDER_QUALITY);
            g.setClip(0, 0, size.width, worldHeight);
            AffineTransform pixels = g.getTransform();
            g.scale(scale, scale);
            drawWorld(g, map, traffic);
            overlay.drawInWorld(g);
            g.setTransform(pixels);
            LabelPlacer labels = drawLabels(g, map, traffic, new Rectangle2D.Double(0, 0, size.width, worldHeight));
            overlay.drawLabelled(g, labels);
            g.setClip(null);
            g.setColor(MapStyle.FRAME);
            g.fillRect(0, worldHeight, size.width, Math.max(1, scale / 3));
            new CaptionPainter(g, style).paint(map, worldHeight + Math.max(1, scale / 3), size.width, size.height);
        } finally {
            g.dispose();
        }
        return image;
    }

    /** Writes the picture atomically: to a temporary file in the same folder, then moved into place. */
    public void writePng(WorldMap map, Path file) throws IOException {
        writeAtomically(render(map), file);
    }

    /**
     * Writes {@code image} as a PNG to {@code file}, whole or not at all (see {@link OutputFile}); a failure
     * names the file and its cause, not ImageIO's "I/O error writing PNG file!".
     */
    public static void writeAtomically(BufferedImage image, Path file) throws IOException {
        try (OutputFile out = OutputFile.open(file)) {
            boolean written;
            try {
                written = ImageIO.write(image, "png", out.stream());
            } catch (IOException e) {
                throw IoReason.about(file, e);
            }
            if (!written) {
                throw new IOException("no PNG writer available to write " + file);
            }
            out.commit();
        }
    }

    /** Height of the world area in pixels at a scale: where the caption strip starts. */
    public static int worldHeightPixels(int pixelsPerMetre) {
        return (int) Math.round(Dimensions.WORLD_HEIGHT * pixelsPerMetre);
    }

    /**
     * Draws the world (no labels, no caption) on {@code g}, whose user space must already be in
     * metres at this renderer's scale; lets other pictures draw a map and their own things on it.
     */
    void drawWorld(Graphics2D g, WorldMap map) {
        drawWorld(g, map, true);
    }

    private void drawWorld(Graphics2D g, WorldMap map, boolean traffic) {
        Layout layout = map.layout();
        RoadNetwork network = RoadNetwork.of(layout);
        MapShapes shapes = new MapShapes(g, style);

        g.setColor(MapStyle.GRASS);
        g.fill(new Rectangle2D.Double(0, 0, Dimensions.WORLD_WIDTH, Dimensions.WORLD_HEIGHT));
        g.setColor(MapStyle.GRID);
        g.setStroke(style.pixelStroke(1));
        for (int x = 10; x < Dimensions.WORLD_WIDTH; x += 10) {
            g.draw(new Line2D.Double(x, 0, x, Dimensions.WORLD_HEIGHT));
        }
        for (int y = 10; y < Dimensions.WORLD_HEIGHT; y += 10) {
            g.draw(new Line2D.Double(0, y, Dimensions.WORLD_WIDTH, y));
        }

        g.setColor(MapStyle.ASPHALT);
        for (Rect surface : network.surfaces()) {
            g.fill(MapShapes.rectangle(surface));
        }
        for (Junction junction : layout.junctions()) {
            g.setColor(junction.isDeadEnd() ? MapStyle.DEAD_END : MapStyle.T_JUNCTION);
            g.fill(MapShapes.rectangle(junction.square()));
            if (junction.isDeadEnd()) {
                shapes.barrier(junction.square(), junction.arms().get(0).opposite(), style.atLeastPixels(0.6, 3));
            }
        }
        for (Marking marking : network.markings()) {
            drawMarking(g, marking);
        }
        for (ParkedCar car : layout.parkedCars()) {
            shapes.box(car.footprint(), MapStyle.PARKED_CAR, MapStyle.PARKED_OUTLINE, 1.2);
        }
        for (StartPose pose : traffic ? map.movingCars() : java.util.List.<StartPose>of()) {
            Box body = pose.footprint(Dimensions.CAR_LENGTH, Dimensions.CAR_WIDTH);
            shapes.movingCar(body, pose.position().x(), pose.position().y(), pose.heading().bearing());
        }
        layout.target().ifPresent(t -> shapes.target(t.position().x(), t.position().y(), MapStyle.TARGET_RADIUS));
        layout.carStart().ifPresent(pose -> shapes.autonomousCar(
                pose.footprint(Dimensions.AUTONOMOUS_CAR_LENGTH, Dimensions.AUTONOMOUS_CAR_WIDTH),
                pose.position().x(), pose.position().y(), pose.heading().bearing()));
    }

    /** Edge lines solid white, the centre line dashed yellow; each at least 1.5 pixels wide. */
    private void drawMarking(Graphics2D g, Marking marking) {
        Rect s = marking.strip();
        boolean horizontal = s.width() >= s.height();
        double thin = horizontal ? s.height() : s.width();
        double wide = style.atLeastPixels(thin, 1.5);
        double mid = horizontal ? (s.minY() + s.maxY()) / 2 : (s.minX() + s.maxX()) / 2;
        Line2D line = horizontal
                ? new Line2D.Double(s.minX(), mid, s.maxX(), mid)
                : new Line2D.Double(mid, s.minY(), mid, s.maxY());
        if (marking.kind() == MarkingKind.EDGE) {
            g.setColor(MapStyle.EDGE_LINE);
            g.setStroke(new BasicStroke((float) wide, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER));
        } else {
            g.setColor(MapStyle.CENTRE_LINE);
            g.setStroke(new BasicStroke((float) wide, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10f,
                    new float[] {2.0f, 1.0f}, 0f));
        }
        g.draw(line);
    }

    private LabelPlacer drawLabels(Graphics2D g, WorldMap map, boolean traffic, Rectangle2D bounds) {
        Layout layout = map.layout();
        LabelPlacer labels = new LabelPlacer(g, style, bounds);
        double r = MapStyle.TARGET_RADIUS * scale;
        for (ParkedCar car : layout.parkedCars()) {
            labels.reserve(pixelBounds(car.footprint().bounds()));
        }
        for (StartPose pose : traffic ? map.movingCars() : java.util.List.<StartPose>of()) {
            labels.reserve(pixelBounds(pose.footprint(Dimensions.CAR_LENGTH, Dimensions.CAR_WIDTH).bounds()));
        }
        layout.target().ifPresent(t -> labels.reserve(new Rectangle2D.Double(
                t.position().x() * scale - r, t.position().y() * scale - r, 2 * r, 2 * r)));
        layout.carStart().ifPresent(pose -> labels.reserve(pixelBounds(autonomousCarWithArrow(pose))));
        layout.target().ifPresent((Target t) ->
                labels.place("Target", t.position().x() * scale, t.position().y() * scale, r + 2, r, MapStyle.TARGET));
        layout.carStart().ifPresent(pose -> {
            Box body = pose.footprint(Dimensions.AUTONOMOUS_CAR_LENGTH, Dimensions.AUTONOMOUS_CAR_WIDTH);
            labels.place("AR", body.centre().x() * scale, body.centre().y() * scale, 1.2 * scale,
                    1.5 * scale, MapStyle.AUTONOMOUS_CAR);
        });
        return labels;
    }

    /** The area the autonomous car's symbol covers: its body and the arrow ahead of it. */
    private static Rect autonomousCarWithArrow(StartPose pose) {
        Rect body = pose.footprint(Dimensions.AUTONOMOUS_CAR_LENGTH, Dimensions.AUTONOMOUS_CAR_WIDTH).bounds();
        double tipX = pose.position().x() + pose.heading().dx() * MapShapes.AR_ARROW_AHEAD;
        double tipY = pose.position().y() + pose.heading().dy() * MapShapes.AR_ARROW_AHEAD;
        return new Rect(Math.min(body.minX(), tipX), Math.min(body.minY(), tipY),
                Math.max(body.maxX(), tipX), Math.max(body.maxY(), tipY));
    }

    private Rectangle2D pixelBounds(Rect r) {
        return new Rectangle2D.Double(r.minX() * scale, r.minY() * scale, r.width() * scale, r.height() * scale);
    }

    private static void checkScale(int pixelsPerMetre) {
        if (pixelsPerMetre < 1 || pixelsPerMetre > MAX_SCALE) {
            throw new IllegalArgumentException("the map scale must be 1 to " + MAX_SCALE
                    + " pixels per metre, got " + pixelsPerMetre);
        }
    }
}
