package sitcov.world;

import static sitcov.world.Dimensions.JUNCTION_END_MARGIN;
import static sitcov.world.Dimensions.MIN_ROAD_LENGTH;
import static sitcov.world.Dimensions.WORLD_HEIGHT;
import static sitcov.world.Dimensions.WORLD_WIDTH;
import static sitcov.world.Dimensions.rounded;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import sitcov.geom.Vec2;

/**
 * Grows and prunes a map's road tree the way the generator grows it ({@link RoadTreeBuilder};
 * src/main/java/sitcov/cli/README.md, "Maps and situation files"): a branch
 * leaves its parent road at a T-junction at least 9 m from the parent's ends, keeps 1 m from every
 * other road, and ends in a dead end. Only a leaf branch (no branch of its own) can be removed, so
 * the roads stay a tree. Road and junction ids stay their indices, as situation files require.
 */
final class BranchRoads {
    private BranchRoads() {
    }

    /** A branch from {@code along} on road {@code parentId}, {@code length} metres across it (negative: towards 0). */
    static Optional<WorldMap> add(WorldMap map, int parentId, double along, double length) {
        Layout l = map.layout();
        if (parentId < 0 || parentId >= l.roads().size()) {
            return Optional.empty();
        }
        Road parent = l.roads().get(parentId);
        double at = rounded(along);
        if (at - parent.from() < JUNCTION_END_MARGIN || parent.to() - at < JUNCTION_END_MARGIN) {
            return Optional.empty();
        }
        Vec2 centre = parent.point(at, parent.centre());
        Axis axis = parent.axis().other();
        double extent = axis == Axis.EAST_WEST ? WORLD_WIDTH : WORLD_HEIGHT;
        double from = axis == Axis.EAST_WEST ? centre.x() : centre.y();
        double to = rounded(Math.max(0, Math.min(extent, from + length)));
        if (Math.abs(to - from) < MIN_ROAD_LENGTH) {
            return Optional.empty();
        }
        Vec2 end = axis == Axis.EAST_WEST ? new Vec2(to, centre.y()) : new Vec2(centre.x(), to);
        Road branch = Road.between(l.roads().size(), centre, end);
        if (!RoadTreeBuilder.isClearOfAllBut(branch, parent, l.roads())) {
            return Optional.empty();
        }
        List<Road> roads = new ArrayList<>(l.roads());
        roads.add(branch);
        List<Junction> junctions = new ArrayList<>(l.junctions());
        junctions.add(RoadTreeBuilder.withArms(junctions.size(), centre, roads));
        junctions.add(RoadTreeBuilder.withArms(junctions.size(), RoadTreeBuilder.deadEndCentre(branch, end), roads));
        Layout edited = new Layout(l.seed(), roads, junctions, l.parkedCars(), l.target(), l.carStart(),
                l.junctionAttempts(), l.parkedCarsRequested(), l.omissions());
        return Optional.of(new WorldMap(edited, map.movingCars(), map.movingCarsRequested(), map.movingCarOmissions()));
    }

    /**
     * Road {@code roadId} taken away with its T-junction and dead end, if it is a leaf branch and holds
     * neither the Target nor the car's start; its parked cars go with it, and moving cars that stood
     * on it are recorded as omissions.
     */
    static Optional<WorldMap> remove(WorldMap map, int roadId, String edit) {
        Layout l = map.layout();
        if (roadId <= 0 || roadId >= l.roads().size()) {
            return Optional.empty();
        }
        Road road = l.roads().get(roadId);
        Optional<Junction> meeting = l.junctions().stream().filter(j -> !j.isDeadEnd()
                && (j.centre().equals(road.start()) || j.centre().equals(road.end()))).findFirst();
        boolean leaf = l.junctions().stream().noneMatch(j -> !j.isDeadEnd() && road.carries(j.centre())
                && meeting.map(m -> m != j).orElse(true));
        boolean holdsTarget = l.target().map(t -> t.roadId() == roadId).orElse(false);
        boolean holdsStart = l.carStart().map(s -> road.contains(s.position().x(), s.position().y())).orElse(false);
        if (meeting.isEmpty() || !leaf || holdsTarget || holdsStart) {
            return Optional.empty();
        }
        List<Road> roads = new ArrayList<>();
        for (Road r : l.roads()) {
            if (r.id() != roadId) {
                roads.add(new Road(roads.size(), r.axis(), r.centre(), r.from(), r.to()));
            }
        }
        List<Junction> junctions = new ArrayList<>();
        for (Junction j : l.junctions()) {
            if (j != meeting.get() && !(j.isDeadEnd() && road.carries(j.centre()))) {
                junctions.add(new Junction(junctions.size(), j.centre(), j.armNorth(), j.armEast(), j.armSouth(),
                        j.armWest()));
            }
        }
        List<ParkedCar> parked = new ArrayList<>();
        for (ParkedCar c : l.parkedCars()) {
            if (c.roadId() != roadId) {
                // ids are indices: the cars after one that went move up
                parked.add(new ParkedCar(parked.size(), renumbered(c.roadId(), roadId), c.centre(), c.axis()));
            }
        }
        Optional<Target> target = l.target().map(t -> new Target(t.position(), renumbered(t.roadId(), roadId)));
        List<StartPose> moving = new ArrayList<>();
        List<Omission> omissions = new ArrayList<>(map.movingCarOmissions());
        for (StartPose s : map.movingCars()) {
            if (road.contains(s.position().x(), s.position().y())) {
                omissions.add(new Omission(String.format(Locale.ROOT, "moving car at %.3f %.3f",
                        s.position().x(), s.position().y()), "its road went with " + edit));
            } else {
                moving.add(s);
            }
        }
        Layout edited = new Layout(l.seed(), roads, junctions, parked, target, l.carStart(), l.junctionAttempts(),
                l.parkedCarsRequested(), l.omissions());
        return Optional.of(new WorldMap(edited, moving, map.movingCarsRequested(), omissions));
    }

    private static int renumbered(int id, int removed) {
        return id > removed ? id - 1 : id;
    }
}
