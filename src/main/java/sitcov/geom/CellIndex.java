package sitcov.geom;

import java.util.ArrayList;
import java.util.List;

/**
 * Which of a list of rectangles reach into the cell of a square grid a point falls in: each cell
 * lists, in the list's order, the index of every rectangle that touches it. A caller that makes
 * each rectangle a margin larger than what it stands for gets every one that can hold a point,
 * whatever the rounding in finding the point's cell, and a scan of that list in order finds what a
 * scan of all would. Immutable once made.
 */
public final class CellIndex {
    private static final int[] NONE = new int[0];

    private final double cell;
    private final double minX;
    private final double minY;
    private final int columns;
    private final int rows;
    private final int[][] cells;

    /** An index of {@code boxes} over cells {@code cell} metres square. */
    public CellIndex(List<Rect> boxes, double cell) {
        this.cell = cell;
        if (boxes.isEmpty()) {
            minX = 0;
            minY = 0;
            columns = 0;
            rows = 0;
            cells = new int[0][];
            return;
        }
        double loX = Double.POSITIVE_INFINITY;
        double loY = Double.POSITIVE_INFINITY;
        double hiX = Double.NEGATIVE_INFINITY;
        double hiY = Double.NEGATIVE_INFINITY;
        for (Rect box : boxes) {
            loX = Math.min(loX, box.minX());
            loY = Math.min(loY, box.minY());
            hiX = Math.max(hiX, box.maxX());
            hiY = Math.max(hiY, box.maxY());
        }
        minX = loX;
        minY = loY;
        columns = (int) Math.floor((hiX - loX) / cell) + 1;
        rows = (int) Math.floor((hiY - loY) / cell) + 1;
        List<List<Integer>> lists = new ArrayList<>();
        for (int c = 0; c < columns * rows; c++) {
            lists.add(new ArrayList<>());
        }
        for (int index = 0; index < boxes.size(); index++) {
            Rect box = boxes.get(index);
            int c0 = column(box.minX());
            int c1 = column(box.maxX());
            int r0 = row(box.minY());
            int r1 = row(box.maxY());
            for (int r = r0; r <= r1; r++) {
                for (int c = c0; c <= c1; c++) {
                    lists.get(r * columns + c).add(index);
                }
            }
        }
        cells = new int[columns * rows][];
        for (int c = 0; c < cells.length; c++) {
            cells[c] = lists.get(c).stream().mapToInt(Integer::intValue).toArray();
        }
    }

    private int column(double x) {
        return Math.max(0, Math.min(columns - 1, (int) Math.floor((x - minX) / cell)));
    }

    private int row(double y) {
        return Math.max(0, Math.min(rows - 1, (int) Math.floor((y - minY) / cell)));
    }

    /** The indices, in order, of the rectangles that reach into the point's cell; none off the grid (or for NaN). */
    public int[] near(double x, double y) {
        double column = (x - minX) / cell;
        double row = (y - minY) / cell;
        if (!(column >= 0 && column < columns && row >= 0 && row < rows)) {
            return NONE;
        }
        return cells[(int) row * columns + (int) column];
    }
}
