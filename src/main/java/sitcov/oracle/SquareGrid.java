package sitcov.oracle;

import java.util.ArrayList;
import java.util.List;
import sitcov.geom.CellIndex;
import sitcov.geom.Rect;

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

    private CellIndex index;

    SquareGrid(double[] squareX, double[] squareY) {
        List<Rect> reach = new ArrayList<>(squareX.length);
        for (int j = 0; j < squareX.length; j++) {
            reach.add(new Rect(squareX[j] - REACH - MARGIN, squareY[j] - REACH - MARGIN,
                    squareX[j] + REACH + MARGIN, squareY[j] + REACH + MARGIN));
        }
        this.index = new CellIndex(reach, CELL);
    }

    /** The squares, in order, a footprint centred at the point may reach into; none off the grid (or for NaN). */
    int[] near(double x, double y) {
        return index.near(x, y);
    }
}
