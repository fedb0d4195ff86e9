package sitcov.report;

import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.geom.AffineTransform;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import javax.imageio.IIOImage;
import javax.imageio.ImageIO;
import javax.imageio.ImageTypeSpecifier;
import javax.imageio.ImageWriteParam;
import javax.imageio.ImageWriter;
import javax.imageio.metadata.IIOMetadata;
import javax.imageio.metadata.IIOMetadataNode;
import javax.imageio.stream.ImageOutputStream;
import sitcov.geom.Box;
import sitcov.world.WorldMap;

/**
 * The fault-free run and its faulty twin as one animated GIF (ImageIO's GIF writer): both maps
 * side by side at a small scale, every vehicle drawn at each frame, the tick and the accidents so
 * far written above each; it loops. Frames are one a second of simulated time by default.
 */
public final class ReplayAnimation {
    /** Pixels per metre: two maps side by side fit a laptop screen. */
    static final int SCALE = 3;
    /** Hundredths of a second a frame is shown. */
    static final int DELAY = 8;
    private static final int TITLE = 24;

    private ReplayAnimation() {
    }

    /** Writes the GIF; {@code labels} name the two sides. */
    public static void write(WorldMap map, List<FrameRecorder.Frame> left, List<FrameRecorder.Frame> right,
                             String[] labels, Path file) throws IOException {
        BufferedImage base = new MapRenderer(SCALE).renderWithoutTraffic(map);
        int frames = Math.max(left.size(), right.size());
        Path tmp = file.resolveSibling(file.getFileName() + ".tmp");
        ImageWriter writer = ImageIO.getImageWritersByFormatName("gif").next();
        try (ImageOutputStream out = ImageIO.createImageOutputStream(tmp.toFile())) {
            writer.setOutput(out);
            writer.prepareWriteSequence(null);
            for (int i = 0; i < frames; i++) {
                BufferedImage frame = new BufferedImage(2 * base.getWidth() + 8, TITLE + base.getHeight(),
                        BufferedImage.TYPE_INT_RGB);
                Graphics2D g = frame.createGraphics();
                try {
                    g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
                    g.setColor(MapStyle.CAPTION);
                    g.fillRect(0, 0, frame.getWidth(), frame.getHeight());
                    side(g, base, left.get(Math.min(i, left.size() - 1)), labels[0], 0);
                    side(g, base, right.get(Math.min(i, right.size() - 1)), labels[1], base.getWidth() + 8);
                } finally {
                    g.dispose();
                }
                writer.writeToSequence(new IIOImage(frame, null, metadata(writer, i == 0)), null);
            }
            writer.endWriteSequence();
        } finally {
            writer.dispose();
        }
        Files.move(tmp, file, java.nio.file.StandardCopyOption.REPLACE_EXISTING);
    }

    private static void side(Graphics2D g, BufferedImage base, FrameRecorder.Frame f, String label, int x) {
        g.drawImage(base, x, TITLE, null);
        g.setColor(MapStyle.TEXT);
        g.setFont(new Font(Font.SANS_SERIF, Font.BOLD, 13));
        g.drawString(String.format(Locale.ROOT, "%s · t=%d · %d accident%s", label, f.tick(), f.accidents(),
                f.accidents() == 1 ? "" : "s"), x + 6, 17);
        AffineTransform saved = g.getTransform();
        g.translate(x, TITLE);
        g.scale(SCALE, SCALE);
        for (Box b : f.traffic()) {
            fill(g, b, MapStyle.MOVING_CAR, MapStyle.MOVING_OUTLINE);
        }
        if (f.car() != null) {
            fill(g, f.car(), MapStyle.AUTONOMOUS_CAR, MapStyle.AUTONOMOUS_OUTLINE);
            // at three pixels a metre the 2 m car is a speck: a ring finds it at a glance
            g.setColor(MapStyle.AUTONOMOUS_CAR);
            g.setStroke(new java.awt.BasicStroke(0.8f));
            g.draw(new java.awt.geom.Ellipse2D.Double(f.car().centreX() - 4, f.car().centreY() - 4, 8, 8));
        }
        g.setTransform(saved);
    }

    private static void fill(Graphics2D g, Box b, Color fill, Color outline) {
        var shape = MapShapes.polygon(b);
        g.setColor(fill);
        g.fill(shape);
        g.setColor(outline);
        g.setStroke(new java.awt.BasicStroke(0.3f));
        g.draw(shape);
    }

    /** A frame's delay; the first frame also carries the loop-for-ever extension. */
    private static IIOMetadata metadata(ImageWriter writer, boolean first) throws IOException {
        ImageWriteParam param = writer.getDefaultWriteParam();
        IIOMetadata meta = writer.getDefaultImageMetadata(
                ImageTypeSpecifier.createFromBufferedImageType(BufferedImage.TYPE_INT_RGB), param);
        String format = meta.getNativeMetadataFormatName();
        IIOMetadataNode root = (IIOMetadataNode) meta.getAsTree(format);
        IIOMetadataNode control = new IIOMetadataNode("GraphicControlExtension");
        control.setAttribute("disposalMethod", "none");
        control.setAttribute("userInputFlag", "FALSE");
        control.setAttribute("transparentColorFlag", "FALSE");
        control.setAttribute("delayTime", Integer.toString(DELAY));
        control.setAttribute("transparentColorIndex", "0");
        root.appendChild(control);
        if (first) {
            IIOMetadataNode extensions = new IIOMetadataNode("ApplicationExtensions");
            IIOMetadataNode loop = new IIOMetadataNode("ApplicationExtension");
            loop.setAttribute("applicationID", "NETSCAPE");
            loop.setAttribute("authenticationCode", "2.0");
            loop.setUserObject(new byte[] {1, 0, 0});
            extensions.appendChild(loop);
            root.appendChild(extensions);
        }
        meta.setFromTree(format, root);
        return meta;
    }
}
