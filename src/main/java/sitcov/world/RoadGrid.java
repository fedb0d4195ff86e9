package sitcov.world;

import java.util.ArrayList;
import java.util.List;
import sitcov.geom.CellIndex;
import sitcov.geom.Rect;

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

    private final CellIndex index;

    RoadGrid(List<Road> roads) {
        List<Rect> surfaces = new ArrayList<>(roads.size());
        for (Road road : roads) {
            Rect surface = road.surface();
            surfaces.add(new Rect(surface.minX() - MARGIN, surface.minY() - MARGIN, surface.maxX() + MARGIN,
                    surface.maxY() + MARGIN));
        }
        this.index = new CellIndex(surfaces, CELL);
    }

    /** The indices, in road order, of the roads that can hold the point; none off the grid (or for NaN). */
    int[] near(double x, double y) {
        return index.near(x, y);
    }
}
