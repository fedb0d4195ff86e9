package sitcov.vehicles;

import java.util.List;
import sitcov.geom.Compass;
import sitcov.world.Dimensions;
import sitcov.world.Junction;
import sitcov.world.Road;
import sitcov.world.RoadNetwork;

/** Ground-truth lane geometry: which road a car drives along, where its lane is, what junction is next. */
public final class Lanes {
    private Lanes() {
    }

    /** +1 when "to the driver's right" is the road's increasing across coordinate, else −1. */
    public static int rightSign(Compass direction) {
        Compass right = direction.right();
        return right.dx() + right.dy();
    }

    /** The coordinate of ({@code x}, {@code y}) along a road running in {@code direction}: it stays put while the car moves. */
    public static double along(Compass direction, double x, double y) {
        return direction.isNorthSouth() ? y : x;
    }

    /** +1 when driving {@code direction} increases the road's along coordinate, else −1. */
    public static int forwardSign(Compass direction) {
        return direction.dx() + direction.dy();
    }

    /** A road holding the point whose axis runs along {@code direction}, or null. */
    public static Road roadAlong(RoadNetwork network, double x, double y, Compass direction) {
        boolean northSouth = direction.isNorthSouth();
        List<Road> roads = network.roads();
        for (int index : network.roadsNear(x, y)) {
            Road road = roads.get(index);
            if (road.isNorthSouth() == northSouth && road.contains(x, y)) {
                return road;
            }
        }
        return null;
    }

    /**
     * How far the point is to the right of the centre of the lane for {@code direction} (negative:
     * towards the kerb on the left).
     */
    static double offsetFromLaneCentre(Road road, Compass direction, double x, double y) {
        return (road.across(x, y) - road.laneCentre(direction)) * rightSign(direction);
    }

    /** Distance ahead (along {@code direction}) from the point to the near edge of the junction square, which may be negative. */
    public static double distanceToSquare(Junction junction, Compass direction, double x, double y) {
        double along = along(direction, x, y);
        double centre = direction.isNorthSouth() ? junction.centre().y() : junction.centre().x();
        return (centre - along) * forwardSign(direction) - Dimensions.HALF_ROAD;
    }

    /**
     * The nearest junction on {@code road} whose square's far edge is still ahead of the point
     * when driving {@code direction}, or null.
     */
    public static Junction nextJunction(RoadNetwork network, Road road, Compass direction, double x, double y) {
        return nextJunction(network, road, direction, x, y, -1);
    }

    /** The same, passing over the junction with id {@code skip}. */
    public static Junction nextJunction(RoadNetwork network, Road road, Compass direction, double x, double y, int skip) {
        Junction best = null;
        double bestDistance = Double.MAX_VALUE;
        List<Junction> on = network.junctionsOn(road);
        for (int each = 0, count = on.size(); each < count; each++) {
            Junction junction = on.get(each);
            if (junction.id() == skip) {
                continue;
            }
            double d = distanceToSquare(junction, direction, x, y);
            if (d > -Dimensions.JUNCTION_SIZE && d < bestDistance) {
                best = junction;
                bestDistance = d;
            }
        }
        return best;
    }
}
