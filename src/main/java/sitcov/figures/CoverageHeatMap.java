package sitcov.figures;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import java.util.Locale;
import sitcov.coverage.Bins;
import sitcov.coverage.CoverageGrid;
import sitcov.coverage.GridDefinition;
import sitcov.render.MapRenderer;

/**
 * A three-criterion coverage grid drawn as one heat-map slice per bin of the third criterion: rows
 * are bins of the second, columns bins of the first; a cell's shade grows with its map count, an
 * empty cell is white with a grey cross, so uncovered situations stand out.
 */
public final class CoverageHeatMap {
    private static final int CELL = 34;
    private static final int MARGIN = 70;
    private static final int GAP = 90;
    private static final Color EMPTY_MARK = new Color(200, 200, 200);

    private CoverageHeatMap() {
    }

    public static BufferedImage render(CoverageGrid grid, String title) {
        GridDefinition def = grid.definition();
        if (def.criteria().size() != 3) {
            throw new IllegalArgumentException("the heat map draws grids of three criteria, this one has "
                    + def.criteria().size());
        }
        Bins cols = def.bins().get(0);
        Bins rows = def.bins().get(1);
        Bins slices = def.bins().get(2);
        int sliceW = cols.count() * CELL;
        int sliceH = rows.count() * CELL;
        int perRow = 3;
        int sliceRows = (slices.count() + perRow - 1) / perRow;
        int width = MARGIN + perRow * (sliceW + GAP) + 20;
        int height = 60 + sliceRows * (sliceH + MARGIN + 20) + 40;
        int max = 1;
        for (int c = 0; c < grid.cells(); c++) {
            max = Math.max(max, grid.count(c));
        }
        BufferedImage image = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = image.createGraphics();
        try {
            g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
            g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
            g.setColor(Color.WHITE);
            g.fillRect(0, 0, width, height);
            g.setColor(Color.BLACK);
            g.setFont(new Font(Font.SANS_SERIF, Font.BOLD, 15));
            g.drawString(title, 12, 24);
            g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 12));
            g.drawString(String.format(Locale.ROOT, "%d of %d cells covered, %d maps invalid; shade = maps in the cell"
                    + " (darkest = %d); white with a cross = not covered", grid.covered(), grid.cells(), grid.invalid(), max),
                    12, 42);
            for (int s = 0; s < slices.count(); s++) {
                int x0 = MARGIN + (s % perRow) * (sliceW + GAP);
                int y0 = 80 + (s / perRow) * (sliceH + MARGIN + 20);
                g.setColor(Color.BLACK);
                g.setFont(new Font(Font.SANS_SERIF, Font.BOLD, 12));
                g.drawString(def.criteria().get(2).key() + " " + range(slices, s), x0 - 14, y0 - 8);
                g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 10));
                for (int r = 0; r < rows.count(); r++) {
                    for (int c = 0; c < cols.count(); c++) {
                        int cell = def.cellAt(c, r, s);
                        int count = grid.count(cell);
                        int x = x0 + c * CELL;
                        int y = y0 + r * CELL;
                        g.setColor(count == 0 ? Color.WHITE : shade(count, max));
                        g.fillRect(x, y, CELL, CELL);
                        if (count == 0) {
                            g.setColor(EMPTY_MARK);
                            g.drawLine(x + 10, y + 10, x + CELL - 10, y + CELL - 10);
                            g.drawLine(x + CELL - 10, y + 10, x + 10, y + CELL - 10);
                        } else {
                            g.setColor(count * 2 > max ? Color.WHITE : Color.BLACK);
                            String n = Integer.toString(count);
                            g.drawString(n, x + (CELL - g.getFontMetrics().stringWidth(n)) / 2, y + CELL / 2 + 4);
                        }
                    }
                }
                g.setColor(Color.DARK_GRAY);
                g.setStroke(new BasicStroke(1f));
                g.drawRect(x0, y0, sliceW, sliceH);
                for (int r = 0; r < rows.count(); r++) {
                    g.drawString(Integer.toString(r), x0 - 12, y0 + r * CELL + CELL / 2 + 4);
                }
                for (int c = 0; c < cols.count(); c++) {
                    g.drawString(Integer.toString(c), x0 + c * CELL + CELL / 2 - 3, y0 + sliceH + 14);
                }
                g.drawString("columns: " + def.criteria().get(0).key() + " bin", x0, y0 + sliceH + 30);
                g.drawString("rows: " + def.criteria().get(1).key() + " bin", x0, y0 + sliceH + 44);
            }
        } finally {
            g.dispose();
        }
        return image;
    }

    public static void writePng(CoverageGrid grid, String title, Path file) throws IOException {
        MapRenderer.writeAtomically(render(grid, title), file);
    }

    private static String range(Bins bins, int bin) {
        double hi = bins.upper(bin);
        return String.format(Locale.ROOT, "%d: [%s, %s) m", bin, trim(bins.lower(bin)),
                Double.isInfinite(hi) ? "inf" : trim(hi));
    }

    private static String trim(double v) {
        return v == Math.rint(v) ? Long.toString((long) v) : Double.toString(v);
    }

    /** From pale to deep blue with the log of the count, so one map and hundreds both read. */
    private static Color shade(int count, int max) {
        double t = max <= 1 ? 1 : Math.log(count) / Math.log(max);
        int r = (int) Math.round(198 - t * (198 - 8));
        int gr = (int) Math.round(219 - t * (219 - 48));
        int b = (int) Math.round(239 - t * (239 - 107));
        return new Color(r, gr, b);
    }
}
