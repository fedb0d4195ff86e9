package sitcov.world;

import java.util.ArrayList;
import java.util.List;

/**
 * Which roads can hold a point, by the cell of a square grid it falls in: a cell lists, in road
 * order, every road whose surface reaches into it. Each surface is entered a margin larger than it
 * is, far beyond {@link Road#contains}'s tolerance and any rounding in finding a point's cell, so a
 * road that holds a point is always in that point's list, and a scan of the list in order finds
 * what a scan of every road finds. Immutable once made.
 */
final class RoadGrid {
    private static final double CELL = 10;
    private static final double MARGIN = 0.01;
    private static final int[] NONE = new int[0];

    private final double minX;
    private final double minY;
    private final int columns;
    private final int rows;
    private final int[][] cells;

    RoadGrid(List<Road> roads) {
        double loX = Double.POSITIVE_INFINITY;
        double loY = Double.POSITIVE_INFINITY;
        double hiX = Double.NEGATIVE_INFINITY;
        double hiY = Double.NEGATIVE_INFINITY;
        for (Road road : roads) {
            var surface = road.surface();
            loX = Math.min(loX, surface.minX() - MARGIN);
            loY = Math.min(loY, surface.minY() - MARGIN);
            hiX = Math.max(hiX, surface.maxX() + MARGIN);
            hiY = Math.max(hiY, surface.maxY() + MARGIN);
        }
        if (roads.isEmpty()) {
            minX = 0;
            minY = 0;
            columns = 0;
            rows = 0;
            cells = new int[0][];
            return;
        }
        minX = loX;
        minY = loY;
        columns = (int) Math.floor((hiX - loX) / CELL) + 1;
        rows = (int) Math.floor((hiY - loY) / CELL) + 1;
        List<List<Integer>> lists = new ArrayList<>();
        for (int c = 0; c < columns * rows; c++) {
            lists.add(new ArrayList<>());
        }
        for (int index = 0; index < roads.size(); index++) {
            var surface = roads.get(index).surface();
            int c0 = column(surface.minX() - MARGIN);
            int c1 = column(surface.maxX() + MARGIN);
            int r0 = row(surface.minY() - MARGIN);
            int r1 = row(surface.maxY() + MARGIN);
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
        return Math.max(0, Math.min(columns - 1, (int) Math.floor((x - minX) / CELL)));
    }

    private int row(double y) {
        return Math.max(0, Math.min(rows - 1, (int) Math.floor((y - minY) / CELL)));
    }

    /** The indices, in road order, of the roads that can hold the point; none off the grid (or for NaN). */
    int[] near(double x, double y) {
        double column = (x - minX) / CELL;
        double row = (y - minY) / CELL;
        if (!(column >= 0 && column < columns && row >= 0 && row < rows)) {
            return NONE;
        }
        return cells[(int) row * columns + (int) column];
    }
}
