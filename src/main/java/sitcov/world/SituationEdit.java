package sitcov.world;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import sitcov.geom.Compass;
import sitcov.geom.Vec2;

/**
 * One change to a situation that a search makes: the Target or the car's start moved along
 * its road, the Target or the start placed on any road, a parked car added, moved along its road or
 * removed, a branch road added or removed ({@link BranchRoads}), the moving cars placed afresh from
 * another seed, or several of these in a {@link Chain}. An edit applies to a map and gives the edited
 * map only if it keeps every rule of the world ({@link Invariants}); the map it gives is a value like
 * any other, written to a situation file to be replayed. Its {@link #text} names it, so parent + edits
 * is an identity.
 */
public sealed interface SituationEdit {
    /** The edited map, or empty when the edit does not apply or the result breaks a rule of the world. */
    default Optional<WorldMap> apply(WorldMap map) {
        return edit(map).filter(m -> Invariants.violations(m).isEmpty());
    }

    /** The edit made, before the world's rules are checked. */
    Optional<WorldMap> edit(WorldMap map);

    /** A short name, e.g. {@code move-target:+5.00}. */
    String text();

    /**
     * The Target moved {@code by} metres along the line of its road (positive: towards the road's end);
     * carried past the end onto another road, it takes that road's id.
     */
    record MoveTarget(double by) implements SituationEdit {
        @Override
        public Optional<WorldMap> edit(WorldMap map) {
            Layout l = map.layout();
            return l.target().flatMap(t -> road(l, t.roadId()).map(road -> {
                Vec2 p = slide(road, t.position(), by);
                return with(map, targeted(l, new Target(p, roadIdAt(l, road, p))));
            }));
        }

        @Override
        public String text() {
            return String.format(Locale.ROOT, "move-target:%+.2f", by);
        }
    }

    /** The car's start moved {@code by} metres along its road, its heading kept. */
    record MoveStart(double by) implements SituationEdit {
        @Override
        public Optional<WorldMap> edit(WorldMap map) {
            Layout l = map.layout();
            return l.carStart().flatMap(s -> roadAt(l, s.position()).map(road -> with(map,
                    started(l, new StartPose(slide(road, s.position(), by), s.heading())))));
        }

        @Override
        public String text() {
            return String.format(Locale.ROOT, "move-start:%+.2f", by);
        }
    }

    /**
     * The car's start placed at the lane centre nearest ({@code x}, {@code y}) on whichever road is
     * there, facing that lane's legal direction: it may leave its road for another.
     */
    record PlaceStart(double x, double y) implements SituationEdit {
        @Override
        public Optional<WorldMap> edit(WorldMap map) {
            Layout l = map.layout();
            Road road = RoadNetwork.of(l).roadAt(x, y);
            if (road == null) {
                return Optional.empty();
            }
            Compass lane = road.laneDirectionAt(x, y);
            Vec2 p = road.point(Dimensions.rounded(road.along(x, y)), road.laneCentre(lane));
            return Optional.of(with(map, started(l, new StartPose(p, lane))));
        }

        @Override
        public String text() {
            return String.format(Locale.ROOT, "place-start:%.3f:%.3f", x, y);
        }
    }

    /** The Target placed at ({@code x}, {@code y}), on whichever road is there: it may leave its road for another. */
    record PlaceTarget(double x, double y) implements SituationEdit {
        @Override
        public Optional<WorldMap> edit(WorldMap map) {
            Layout l = map.layout();
            double px = Dimensions.rounded(x);
            double py = Dimensions.rounded(y);
            Road road = RoadNetwork.of(l).roadAt(px, py);
            if (road == null) {
                return Optional.empty();
            }
            return Optional.of(with(map, targeted(l, new Target(new Vec2(px, py), road.id()))));
        }

        @Override
        public String text() {
            return String.format(Locale.ROOT, "place-target:%.3f:%.3f", x, y);
        }
    }

    /**
     * The moving cars placed afresh, as the generator places them, from stream {@code seed} instead of
     * the map's own: the same roads, parked cars, Target and start, other traffic.
     */
    record ReseedTraffic(long seed) implements SituationEdit {
        @Override
        public Optional<WorldMap> edit(WorldMap map) {
            Layout l = map.layout();
            List<Omission> omissions = new ArrayList<>();
            Placed<StartPose> moving = new Placement(RoadNetwork.of(l)).movingCars(
                    new sitcov.engine.RandomStreams(seed).stream(MapGenerator.MOVING_CARS_STREAM), l.parkedCars(),
                    l.carStart(), omissions);
            return Optional.of(new WorldMap(l, moving.items(), moving.requested(), omissions));
        }

        @Override
        public String text() {
            return "reseed-traffic:" + seed;
        }
    }

    /**
     * Parked car {@code id} moved {@code by} metres along the line of its road, at the same kerb; carried
     * past the end onto another road, it takes that road's id.
     */
    record MoveParkedCar(int id, double by) implements SituationEdit {
        @Override
        public Optional<WorldMap> edit(WorldMap map) {
            Layout l = map.layout();
            List<ParkedCar> cars = new ArrayList<>(l.parkedCars());
            for (int i = 0; i < cars.size(); i++) {
                ParkedCar c = cars.get(i);
                if (c.id() == id) {
                    Optional<Road> road = road(l, c.roadId());
                    if (road.isEmpty()) {
                        return Optional.empty();
                    }
                    Vec2 p = slide(road.get(), c.centre(), by);
                    cars.set(i, new ParkedCar(c.id(), roadIdAt(l, road.get(), p), p, c.axis()));
                    return Optional.of(with(map, parked(l, cars)));
                }
            }
            return Optional.empty();
        }

        @Override
        public String text() {
            return String.format(Locale.ROOT, "move-parked-car:%d:%+.2f", id, by);
        }
    }

    /** Parked car {@code id} taken away; the cars after it take the ids before them (ids are indices in situation files). */
    record RemoveParkedCar(int id) implements SituationEdit {
        @Override
        public Optional<WorldMap> edit(WorldMap map) {
            Layout l = map.layout();
            List<ParkedCar> cars = l.parkedCars().stream().filter(c -> c.id() != id).toList();
            return cars.size() == l.parkedCars().size() ? Optional.empty()
                    : Optional.of(with(map, parked(l, ParkedCar.numbered(cars))));
        }

        @Override
        public String text() {
            return "remove-parked-car:" + id;
        }
    }

    /** A parked car added at the kerb nearest ({@code x}, {@code y}) on the road there, with the next free id. */
    record AddParkedCar(double x, double y) implements SituationEdit {
        @Override
        public Optional<WorldMap> edit(WorldMap map) {
            Layout l = map.layout();
            Road road = RoadNetwork.of(l).roadAt(x, y);
            if (road == null) {
                return Optional.empty();
            }
            int id = l.parkedCars().stream().mapToInt(ParkedCar::id).max().orElse(-1) + 1;
            List<ParkedCar> cars = new ArrayList<>(l.parkedCars());
            cars.add(new ParkedCar(id, road.id(), RoadNetwork.kerbsidePosition(road, x, y), road.axis()));
            return Optional.of(with(map, parked(l, cars)));
        }

        @Override
        public String text() {
            return String.format(Locale.ROOT, "add-parked-car:%.2f:%.2f", x, y);
        }
    }

    /**
     * A branch road added: it leaves road {@code parent} at {@code along} metres (its along coordinate)
     * at a new T-junction and runs {@code length} metres across it (negative: towards 0) to a new dead end.
     */
    record AddBranchRoad(int parent, double along, double length) implements SituationEdit {
        @Override
        public Optional<WorldMap> edit(WorldMap map) {
            return BranchRoads.add(map, parent, along, length);
        }

        @Override
        public String text() {
            return String.format(Locale.ROOT, "add-branch-road:%d:%.2f:%+.2f", parent, along, length);
        }
    }

    /** Branch road {@code id} removed with its junctions and parked cars, if no branch leaves it and it holds neither the Target nor the start. */
    record RemoveBranchRoad(int id) implements SituationEdit {
        @Override
        public Optional<WorldMap> edit(WorldMap map) {
            return BranchRoads.remove(map, id, text());
        }

        @Override
        public String text() {
            return "remove-branch-road:" + id;
        }
    }

    /**
     * Edits made one after another, each on the map the one before gave, as one edit: the world's
     * rules hold for the map it ends with, not in between (a branch road added where the start stood,
     * then the start placed on the branch, say).
     */
    record Chain(List<SituationEdit> edits) implements SituationEdit {
        public Chain {
            edits = List.copyOf(edits);
            if (edits.isEmpty()) {
                throw new IllegalArgumentException("a chain of edits needs at least one edit");
            }
        }

        @Override
        public Optional<WorldMap> edit(WorldMap map) {
            Optional<WorldMap> edited = Optional.of(map);
            for (SituationEdit e : edits) {
                edited = edited.flatMap(e::edit);
            }
            return edited;
        }

        @Override
        public String text() {
            return String.join("+", edits.stream().map(SituationEdit::text).toList());
        }
    }

    private static Optional<Road> road(Layout layout, int id) {
        return layout.roads().stream().filter(r -> r.id() == id).findFirst();
    }

    private static Optional<Road> roadAt(Layout layout, Vec2 p) {
        return Optional.ofNullable(RoadNetwork.of(layout).roadAt(p.x(), p.y()));
    }

    /** The point {@code by} metres further along {@code road}, at the same distance across it. */
    private static Vec2 slide(Road road, Vec2 p, double by) {
        Vec2 moved = road.point(road.along(p.x(), p.y()) + by, road.across(p.x(), p.y()));
        return new Vec2(Dimensions.rounded(moved.x()), Dimensions.rounded(moved.y()));
    }

    /**
     * The id of the road under {@code p}, which was slid along {@code road}: that road while it holds the
     * point, else the road the slide carried it onto (the world's rules refuse the id of a road that does
     * not hold its element). Off every road it stays {@code road}'s, and the rules refuse the map.
     */
    private static int roadIdAt(Layout layout, Road road, Vec2 p) {
        if (road.contains(p.x(), p.y())) {
            return road.id();
        }
        Road there = RoadNetwork.of(layout).roadAt(p.x(), p.y());
        return there != null ? there.id() : road.id();
    }

    private static Layout targeted(Layout l, Target target) {
        return new Layout(l.seed(), l.roads(), l.junctions(), l.parkedCars(), Optional.of(target), l.carStart(),
                l.junctionAttempts(), l.parkedCarsRequested(), l.omissions());
    }

    private static Layout started(Layout l, StartPose start) {
        return new Layout(l.seed(), l.roads(), l.junctions(), l.parkedCars(), l.target(), Optional.of(start),
                l.junctionAttempts(), l.parkedCarsRequested(), l.omissions());
    }

    private static Layout parked(Layout l, List<ParkedCar> cars) {
        return new Layout(l.seed(), l.roads(), l.junctions(), cars, l.target(), l.carStart(), l.junctionAttempts(),
                l.parkedCarsRequested(), l.omissions());
    }

    private static WorldMap with(WorldMap map, Layout layout) {
        return new WorldMap(layout, map.movingCars(), map.movingCarsRequested(), map.movingCarOmissions());
    }
}
