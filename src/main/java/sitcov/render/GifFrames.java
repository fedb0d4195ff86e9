package sitcov.render;

import java.awt.Color;
import java.awt.image.BufferedImage;
import java.awt.image.DataBufferByte;
import java.awt.image.DataBufferInt;
import java.awt.image.IndexColorModel;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import javax.imageio.IIOImage;
import javax.imageio.ImageIO;
import javax.imageio.ImageTypeSpecifier;
import javax.imageio.ImageWriter;
import javax.imageio.metadata.IIOMetadata;
import javax.imageio.metadata.IIOMetadataNode;
import javax.imageio.stream.ImageOutputStream;
import javax.imageio.stream.MemoryCacheImageOutputStream;
import org.w3c.dom.Node;
import sitcov.results.OutputFile;

/**
 * An animated GIF written frame by frame with ImageIO's GIF writer, kept small: one palette of
 * {@link #COLOURS} for every frame (the first frame's commonest colours and the ones every frame
 * must show exactly), and each frame after the first only the rectangle that changed, its
 * unchanged pixels transparent over the frame before (disposal "do not dispose"). It loops for ever,
 * and is written whole or not at all ({@link OutputFile}).
 */
final class GifFrames implements AutoCloseable {
    /** 63 colours and a transparent one: six bits a pixel. */
    static final int COLOURS = 64;
    private static final String FORMAT = "javax_imageio_gif_image_1.0";

    private final OutputFile file;
    private final ImageOutputStream stream;
    private final ImageWriter writer;
    private final int width;
    private final int height;
    private final List<Color> must;
    private IndexColorModel palette;
    private int transparent;
    private final Map<Integer, Byte> nearest = new HashMap<>();
    private int[] previous;
    private byte[] shown;
    private boolean first = true;
    private boolean ended;

    private GifFrames(OutputFile file, ImageOutputStream stream, ImageWriter writer, int width, int height,
                      List<Color> must) {
        this.file = file;
        this.stream = stream;
        this.writer = writer;
        this.width = width;
        this.height = height;
        this.must = must;
    }

    /** Starts a GIF of frames {@code width} x {@code height}; {@code must} are colours kept exactly. */
    static GifFrames open(Path path, int width, int height, List<Color> must) throws IOException {
        OutputFile file = OutputFile.open(path);
        try {
            ImageOutputStream stream = new MemoryCacheImageOutputStream(file.stream());
            ImageWriter writer = ImageIO.getImageWritersByFormatName("gif").next();
            writer.setOutput(stream);
            writer.prepareWriteSequence(null);
            return new GifFrames(file, stream, writer, width, height, List.copyOf(must));
        } catch (IOException | RuntimeException e) {
            file.close();
            throw e;
        }
    }

    /** Adds a frame (TYPE_INT_RGB, the GIF's size) shown for {@code delay} hundredths of a second. */
    void add(BufferedImage frame, int delay) throws IOException {
        if (frame.getWidth() != width || frame.getHeight() != height || frame.getType() != BufferedImage.TYPE_INT_RGB) {
            throw new IllegalArgumentException("a frame must be an RGB image of " + width + "x" + height);
        }
        int[] rgb = ((DataBufferInt) frame.getRaster().getDataBuffer()).getData();
        if (first) {
            palette(rgb);
            shown = new byte[rgb.length];
            for (int i = 0; i < rgb.length; i++) {
                shown[i] = index(rgb[i]);
            }
            write(shown, 0, 0, width, height, delay);
            previous = rgb.clone();
            first = false;
            return;
        }
        // the rectangle holding every pixel that changed
        int minX = width;
        int minY = height;
        int maxX = -1;
        int maxY = -1;
        for (int y = 0; y < height; y++) {
            int row = y * width;
            for (int x = 0; x < width; x++) {
                if (rgb[row + x] != previous[row + x]) {
                    minX = Math.min(minX, x);
                    maxX = Math.max(maxX, x);
                    minY = Math.min(minY, y);
                    maxY = y;
                }
            }
        }
        if (maxX < 0) { // nothing changed: one transparent pixel carries the delay
            minX = 0;
            minY = 0;
            maxX = 0;
            maxY = 0;
        }
        int w = maxX - minX + 1;
        int h = maxY - minY + 1;
        byte[] part = new byte[w * h];
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                int at = (minY + y) * width + minX + x;
                byte index = index(rgb[at]);
                if (index == shown[at]) {
                    part[y * w + x] = (byte) transparent;
                } else {
                    part[y * w + x] = index;
                    shown[at] = index;
                }
            }
        }
        write(part, minX, minY, w, h, delay);
        previous = rgb.clone();
    }

    /** Ends the GIF and moves it into place. */
    void commit() throws IOException {
        writer.endWriteSequence();
        stream.close();
        ended = true;
        file.commit();
    }

    @Override
    public void close() throws IOException {
        writer.dispose();
        try {
            if (!ended) {
                stream.close();
            }
        } finally {
            file.close();
        }
    }

    /** The colours every frame must show, then the first frame's commonest (ties by value), then transparent. */
    private void palette(int[] rgb) {
        Set<Integer> colours = new LinkedHashSet<>();
        for (Color c : must) {
            colours.add(c.getRGB() & 0xFFFFFF);
        }
        Map<Integer, Integer> counts = new HashMap<>();
        for (int p : rgb) {
            counts.merge(p & 0xFFFFFF, 1, Integer::sum);
        }
        List<Map.Entry<Integer, Integer>> common = new ArrayList<>(counts.entrySet());
        common.sort(Comparator.<Map.Entry<Integer, Integer>>comparingInt(Map.Entry::getValue).reversed()
                .thenComparing(Map.Entry::getKey));
        for (Map.Entry<Integer, Integer> e : common) {
            if (colours.size() >= COLOURS - 1) {
                break;
            }
            colours.add(e.getKey());
        }
        byte[] r = new byte[COLOURS];
        byte[] g = new byte[COLOURS];
        byte[] b = new byte[COLOURS];
        int i = 0;
        for (int c : colours) {
            r[i] = (byte) (c >> 16);
            g[i] = (byte) (c >> 8);
            b[i] = (byte) c;
            i++;
        }
        transparent = COLOURS - 1;
        palette = new IndexColorModel(6, COLOURS, r, g, b, transparent);
    }

    /** The palette entry nearest {@code rgb} (never the transparent one). */
    private byte index(int rgb) {
        int key = rgb & 0xFFFFFF;
        Byte known = nearest.get(key);
        if (known != null) {
            return known;
        }
        int best = 0;
        long bestDistance = Long.MAX_VALUE;
        for (int i = 0; i < transparent; i++) {
            long dr = ((key >> 16) & 0xFF) - palette.getRed(i);
            long dg = ((key >> 8) & 0xFF) - palette.getGreen(i);
            long db = (key & 0xFF) - palette.getBlue(i);
            // weighted as the eye weighs them, roughly
            long distance = 3 * dr * dr + 4 * dg * dg + 2 * db * db;
            if (distance < bestDistance) {
                bestDistance = distance;
                best = i;
            }
        }
        nearest.put(key, (byte) best);
        return (byte) best;
    }

    private void write(byte[] indices, int x, int y, int w, int h, int delay) throws IOException {
        BufferedImage image = new BufferedImage(w, h, BufferedImage.TYPE_BYTE_INDEXED, palette);
        byte[] data = ((DataBufferByte) image.getRaster().getDataBuffer()).getData();
        System.arraycopy(indices, 0, data, 0, indices.length);
        IIOMetadata meta = writer.getDefaultImageMetadata(new ImageTypeSpecifier(image), writer.getDefaultWriteParam());
        IIOMetadataNode root = (IIOMetadataNode) meta.getAsTree(FORMAT);
        IIOMetadataNode descriptor = child(root, "ImageDescriptor");
        descriptor.setAttribute("imageLeftPosition", Integer.toString(x));
        descriptor.setAttribute("imageTopPosition", Integer.toString(y));
        descriptor.setAttribute("imageWidth", Integer.toString(w));
        descriptor.setAttribute("imageHeight", Integer.toString(h));
        descriptor.setAttribute("interlaceFlag", "FALSE");
        IIOMetadataNode control = child(root, "GraphicControlExtension");
        control.setAttribute("disposalMethod", "doNotDispose");
        control.setAttribute("userInputFlag", "FALSE");
        control.setAttribute("transparentColorFlag", first ? "FALSE" : "TRUE");
        control.setAttribute("transparentColorIndex", Integer.toString(transparent));
        control.setAttribute("delayTime", Integer.toString(delay));
        if (first) {
            IIOMetadataNode extensions = child(root, "ApplicationExtensions");
            IIOMetadataNode loop = new IIOMetadataNode("ApplicationExtension");
            loop.setAttribute("applicationID", "NETSCAPE");
            loop.setAttribute("authenticationCode", "2.0");
            loop.setUserObject(new byte[] {1, 0, 0}); // loop for ever
            extensions.appendChild(loop);
        }
        meta.setFromTree(FORMAT, root);
        writer.writeToSequence(new IIOImage(image, null, meta), null);
    }

    private static IIOMetadataNode child(IIOMetadataNode root, String name) {
        for (Node n = root.getFirstChild(); n != null; n = n.getNextSibling()) {
            if (n.getNodeName().equals(name)) {
                return (IIOMetadataNode) n;
            }
        }
        IIOMetadataNode node = new IIOMetadataNode(name);
        root.appendChild(node);
        return node;
    }
}
