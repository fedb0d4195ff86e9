package sitcov.world;

import java.util.List;
import java.util.Optional;
import sitcov.geom.Compass;
import sitcov.geom.Vec2;

/** Hand-built situations every test can use; coordinates are chosen so expected values are easy to check. */
public final class Situations {
    private Situations() {
    }

    /** One east–west road, y = 50, from x = 20 to x = 180, with a dead end at each end. */
    public static Road straightRoad() {
        return new Road(0, Axis.EAST_WEST, 50, 20, 180);
    }

    public static List<Junction> straightRoadDeadEnds() {
        return List.of(
                new Junction(0, new Vec2(23, 50), 0, 23, 0, 0),
                new Junction(1, new Vec2(177, 50), 0, 0, 0, 23));
    }

    /**
     * The straight road with the car starting east-bound at x = 40 (east-bound lane: y = 48.5)
     * and the Target in its lane at x = 150; the given parked cars.
     */
    public static Layout straight(List<ParkedCar> parked) {
        return layout(List.of(straightRoad()), straightRoadDeadEnds(), parked,
                new Target(new Vec2(150, 48.5), 0), new StartPose(new Vec2(40, 48.5), Compass.EAST));
    }

    /** A parked car against the north kerb of the straight road (in the east-bound lane), centred at x. */
    public static ParkedCar parkedInEastboundLane(int id, double x) {
        return new ParkedCar(id, 0, new Vec2(x, 50 - 1.675), Axis.EAST_WEST);
    }

    /**
     * A T: an east–west road y = 30 from x = 10 to 190, and a branch south from (100, 30) to
     * (100, 90). T-junction at (100, 30); dead ends at both ends of the main road and at the
     * branch's south end.
     */
    public static Layout tee() {
        List<Road> roads = List.of(new Road(0, Axis.EAST_WEST, 30, 10, 190), new Road(1, Axis.NORTH_SOUTH, 100, 30, 90));
        List<Junction> junctions = List.of(
                new Junction(0, new Vec2(100, 30), 0, 23, 23, 23),
                new Junction(1, new Vec2(13, 30), 0, 23, 0, 0),
                new Junction(2, new Vec2(187, 30), 0, 0, 0, 23),
                new Junction(3, new Vec2(100, 87), 23, 0, 0, 0));
        return layout(roads, junctions, List.of(), new Target(new Vec2(100.0 + 1.5, 70), 1),
                new StartPose(new Vec2(40, 28.5), Compass.EAST));
    }

    public static Layout layout(List<Road> roads, List<Junction> junctions, List<ParkedCar> parked,
                                Target target, StartPose start) {
        return new Layout(0, roads, junctions, parked, Optional.ofNullable(target), Optional.ofNullable(start),
                0, parked.size(), List.of());
    }

    public static WorldMap withoutTraffic(Layout layout) {
        return new WorldMap(layout, List.of(), 0, List.of());
    }

    public static WorldMap withTraffic(Layout layout, List<StartPose> movingCars) {
        return new WorldMap(layout, movingCars, movingCars.size(), List.of());
    }
}
