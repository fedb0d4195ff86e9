package sitcov.render;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;

/**
 * The look of a rendered map: colours, and the sizes that depend on the scale. Lines thinner than
 * a pixel or two vanish at a few pixels per metre, so painted markings and outlines get a minimum
 * width in pixels; everything else is drawn to scale.
 */
final class MapStyle {
    static final Color GRASS = new Color(0x9DBF84);
    static final Color GRID = new Color(0x91B478);
    static final Color ASPHALT = new Color(0x4B4B4F);
    static final Color T_JUNCTION = new Color(0x67676F);
    static final Color DEAD_END = new Color(0x6A5F58);
    static final Color BARRIER_A = new Color(0xD7263D);
    static final Color BARRIER_B = Color.WHITE;
    static final Color EDGE_LINE = Color.WHITE;
    static final Color CENTRE_LINE = new Color(0xFFE066);
    static final Color PARKED_CAR = new Color(0x2E5C9A);
    static final Color PARKED_OUTLINE = new Color(0xDCE6F5);
    static final Color MOVING_CAR = new Color(0xB84FD0);
    static final Color MOVING_OUTLINE = new Color(0x2A0F33);
    static final Color AUTONOMOUS_CAR = new Color(0x00E5FF);
    static final Color AUTONOMOUS_OUTLINE = Color.BLACK;
    static final Color TARGET = new Color(0xE8311E);
    static final Color TARGET_RING = Color.WHITE;
    static final Color LABEL_BACKGROUND = new Color(255, 255, 255, 225);
    static final Color LABEL_BORDER = new Color(0x333333);
    static final Color TEXT = new Color(0x1E1E1E);
    static final Color CAPTION = new Color(0xF3F1EC);
    static final Color FRAME = new Color(0x3A3A3A);

    /** Radius of the Target's bullseye, in metres. */
    static final double TARGET_RADIUS = 2.4;

    private final int scale;

    MapStyle(int pixelsPerMetre) {
        this.scale = pixelsPerMetre;
    }

    int scale() {
        return scale;
    }

    /** A width in metres, widened to at least {@code minPixels} pixels, in metres. */
    double atLeastPixels(double metres, double minPixels) {
        return Math.max(metres, minPixels / scale);
    }

    /** A stroke of the given pixel width, for drawing in metre coordinates. */
    BasicStroke pixelStroke(double pixels) {
        return new BasicStroke((float) (pixels / scale), BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER);
    }

    /** The caption and label font size in pixels for a scale: readable, never huge. */
    static int fontSize(int pixelsPerMetre) {
        return Math.max(9, Math.min(28, 2 * pixelsPerMetre + 2));
    }

    static int lineHeight(int pixelsPerMetre) {
        return Math.round(fontSize(pixelsPerMetre) * 1.45f);
    }

    /** Three text rows (title, counts, legend) plus padding. */
    static int captionHeight(int pixelsPerMetre) {
        return 3 * lineHeight(pixelsPerMetre) + 2 * padding(pixelsPerMetre);
    }

    static int padding(int pixelsPerMetre) {
        return Math.max(4, fontSize(pixelsPerMetre) / 2);
    }

    Font font(int style) {
        return new Font(Font.SANS_SERIF, style, fontSize(scale));
    }

    Font smallFont() {
        return new Font(Font.SANS_SERIF, Font.PLAIN, Math.max(8, fontSize(scale) - 2));
    }
}
