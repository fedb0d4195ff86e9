package sitcov.oracle;

import java.util.ArrayList;
import java.util.List;

/**
 * Which junction squares a footprint can reach into, by the cell of a square grid its centre falls
 * in: a cell lists, in square order, every square whose centre lies within {@link #REACH} of the
 * cell on both axes. A footprint whose centre is at least {@code REACH} from a square's centre on
 * either axis cannot overlap it ({@code NearMisses.inSquare} says so first); the margin on top
 * absorbs any rounding in finding a centre's cell. Immutable once made.
 */
final class SquareGrid {
    /** Half a square plus the largest half-diagonal of a footprint this grid answers for. */
    static final double REACH = 12;
    private static final double CELL = 10;
    private static final double MARGIN = 0.01;
    private static final int[] NONE = new int[0];

    private final double minX;
    private final double minY;
    private final int columns;
    private final int rows;
    private final int[][] cells;

    SquareGrid(double[] squareX, double[] squareY) {
        int n = squareX.length;
        if (n == 0) {
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
        for (int j = 0; j < n; j++) {
            loX = Math.min(loX, squareX[j] - REACH - MARGIN);
            loY = Math.min(loY, squareY[j] - REACH - MARGIN);
            hiX = Math.max(hiX, squareX[j] + REACH + MARGIN);
            hiY = Math.max(hiY, squareY[j] + REACH + MARGIN);
        }
        minX = loX;
        minY = loY;
        columns = (int) Math.floor((hiX - loX) / CELL) + 1;
        rows = (int) Math.floor((hiY - loY) / CELL) + 1;
        List<List<Integer>> lists = new ArrayList<>();
        for (int c = 0; c < columns * rows; c++) {
            lists.add(new ArrayList<>());
        }
        for (int j = 0; j < n; j++) {
            int c0 = column(squareX[j] - REACH - MARGIN);
            int c1 = column(squareX[j] + REACH + MARGIN);
            int r0 = row(squareY[j] - REACH - MARGIN);
            int r1 = row(squareY[j] + REACH + MARGIN);
            for (int r = r0; r <= r1; r++) {
                for (int c = c0; c <= c1; c++) {
                    lists.get(r * columns + c).add(j);
                }
            }
        }
        cells = new int[columns * rows][];
        for (int c = 0; c < cells.length; c++) {
            cells[c] = lists.get(c).stream().mapToInt(Integer::intValue).toArray();
        }
    }

    private int column(double x) {
        return Math.max(0, Math.min(columns - 1, (int) Math.floor((x - minX) / CELL)));
    }

    private int row(double y) {
        return Math.max(0, Math.min(rows - 1, (int) Math.floor((y - minY) / CELL)));
    }

    /** The squares, in order, a footprint centred at the point may reach into; none off the grid (or for NaN). */
    int[] near(double x, double y) {
        double column = (x - minX) / CELL;
        double row = (y - minY) / CELL;
        if (!(column >= 0 && column < columns && row >= 0 && row < rows)) {
            return NONE;
        }
        return cells[(int) row * columns + (int) column];
    }
}
