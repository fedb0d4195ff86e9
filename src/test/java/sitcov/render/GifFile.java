package sitcov.render;

import java.awt.Graphics2D;
import java.awt.Rectangle;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import javax.imageio.ImageIO;
import javax.imageio.ImageReader;
import javax.imageio.metadata.IIOMetadataNode;
import javax.imageio.stream.ImageInputStream;

/** An animated GIF read back as a viewer shows it: each frame laid over the ones before; a fixture for tests. */
public record GifFile(List<Rectangle> regions, List<Integer> delays, List<BufferedImage> shown) {
    private static final String FORMAT = "javax_imageio_gif_image_1.0";

    /** Reads {@code file}, keeping the whole picture only at frames {@code keep} (negative: from the end). */
    public static GifFile read(Path file, int... keep) throws IOException {
        ImageReader reader = ImageIO.getImageReadersByFormatName("gif").next();
        try (ImageInputStream in = ImageIO.createImageInputStream(file.toFile())) {
            reader.setInput(in);
            int n = reader.getNumImages(true);
            List<Integer> wanted = new ArrayList<>();
            for (int k : keep) {
                wanted.add(k < 0 ? n + k : k);
            }
            List<Rectangle> regions = new ArrayList<>();
            List<Integer> delays = new ArrayList<>();
            BufferedImage[] shown = new BufferedImage[keep.length];
            BufferedImage canvas = null;
            for (int i = 0; i < n; i++) {
                BufferedImage part = reader.read(i);
                IIOMetadataNode root = (IIOMetadataNode) reader.getImageMetadata(i).getAsTree(FORMAT);
                IIOMetadataNode d = (IIOMetadataNode) root.getElementsByTagName("ImageDescriptor").item(0);
                IIOMetadataNode c = (IIOMetadataNode) root.getElementsByTagName("GraphicControlExtension").item(0);
                Rectangle r = new Rectangle(Integer.parseInt(d.getAttribute("imageLeftPosition")),
                        Integer.parseInt(d.getAttribute("imageTopPosition")), part.getWidth(), part.getHeight());
                regions.add(r);
                delays.add(Integer.parseInt(c.getAttribute("delayTime")));
                if (canvas == null) {
                    canvas = new BufferedImage(part.getWidth(), part.getHeight(), BufferedImage.TYPE_INT_RGB);
                }
                Graphics2D g = canvas.createGraphics();
                g.drawImage(part, r.x, r.y, null); // transparent pixels leave the frame before showing
                g.dispose();
                for (int k = 0; k < keep.length; k++) {
                    if (wanted.get(k) == i) {
                        BufferedImage copy = new BufferedImage(canvas.getWidth(), canvas.getHeight(), BufferedImage.TYPE_INT_RGB);
                        copy.setData(canvas.getData());
                        shown[k] = copy;
                    }
                }
            }
            return new GifFile(regions, delays, List.of(shown));
        } finally {
            reader.dispose();
        }
    }

    public int frames() {
        return regions.size();
    }
}
