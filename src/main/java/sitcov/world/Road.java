package sitcov.world;

import static sitcov.world.Dimensions.HALF_ROAD;
import static sitcov.world.Dimensions.LANE_WIDTH;

import sitcov.geom.Compass;
import sitcov.geom.Rect;
import sitcov.geom.Vec2;

/**
 * A straight two-way road, 6 m wide, with two 3 m lanes and left-hand traffic: on a north–south
 * road the north-bound lane is the west half; on an east–west road the east-bound lane is the
 * north half.
 *
 * @param id     index of the road in its layout
 * @param axis   orientation
 * @param centre the centre line's coordinate across the road (x for north–south, y for east–west)
 * @param from   the smaller end coordinate along the road
 * @param to     the larger end coordinate along the road
 */
public record Road(int id, Axis axis, double centre, double from, double to) {
    public Road {
        if (!(from < to)) {
            throw new IllegalArgumentException("road " + id + " needs from < to, got " + from + ".." + to);
        }
    }

    /** The road between two points that share one coordinate. */
    public static Road between(int id, Vec2 a, Vec2 b) {
        if (a.x() == b.x()) {
            return new Road(id, Axis.NORTH_SOUTH, a.x(), Math.min(a.y(), b.y()), Math.max(a.y(), b.y()));
        }
        if (a.y() == b.y()) {
            return new Road(id, Axis.EAST_WEST, a.y(), Math.min(a.x(), b.x()), Math.max(a.x(), b.x()));
        }
        throw new IllegalArgumentException("road " + id + " is not axis-aligned: " + a + " to " + b);
    }

    public double length() {
        return to - from;
    }

    public boolean isNorthSouth() {
        return axis == Axis.NORTH_SOUTH;
    }

    /** The end at {@code from}: the north end of a north–south road, the west end of an east–west one. */
    public Vec2 start() {
        return point(from, centre);
    }

    public Vec2 end() {
        return point(to, centre);
    }

    /** The road surface: the centre line ± 3 m, exactly between the ends. */
    public Rect surface() {
        return isNorthSouth()
                ? new Rect(centre - HALF_ROAD, from, centre + HALF_ROAD, to)
                : new Rect(from, centre - HALF_ROAD, to, centre + HALF_ROAD);
    }

    public boolean contains(double x, double y) {
        double along = along(x, y);
        double across = across(x, y);
        return along >= from - 1e-9 && along <= to + 1e-9 && Math.abs(across - centre) <= HALF_ROAD + 1e-9;
    }

    /** The coordinate of a point along this road (y for north–south, x for east–west). */
    public double along(double x, double y) {
        return isNorthSouth() ? y : x;
    }

    /** The coordinate of a point across this road (x for north–south, y for east–west). */
    public double across(double x, double y) {
        return isNorthSouth() ? x : y;
    }

    /** The point at the given along and across coordinates. */
    public Vec2 point(double along, double across) {
        return isNorthSouth() ? new Vec2(across, along) : new Vec2(along, across);
    }

    /** The legal direction of the lane half holding the point (a point on the centre line counts as the second half). */
    public Compass laneDirectionAt(double x, double y) {
        boolean firstHalf = across(x, y) < centre;
        if (isNorthSouth()) {
            return firstHalf ? Compass.NORTH : Compass.SOUTH;
        }
        return firstHalf ? Compass.EAST : Compass.WEST;
    }

    /** The across coordinate of the centre of the lane that carries traffic in {@code direction}. */
    public double laneCentre(Compass direction) {
        if (Axis.of(direction) != axis) {
            throw new IllegalArgumentException("road " + id + " runs " + axis + ", it has no lane heading " + direction);
        }
        boolean firstHalf = direction == Compass.NORTH || direction == Compass.EAST;
        return firstHalf ? centre - LANE_WIDTH / 2 : centre + LANE_WIDTH / 2;
    }

    /** Whether this road's axis line passes through the point (a junction centre, say). */
    public boolean carries(Vec2 p) {
        double along = along(p.x(), p.y());
        return across(p.x(), p.y()) == centre && along >= from && along <= to;
    }
}
