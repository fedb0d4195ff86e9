package sitcov.drivers;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Optional;
import java.util.random.RandomGenerator;
import sitcov.coverage.Bins;
import sitcov.coverage.Criterion;
import sitcov.coverage.GridDefinition;
import sitcov.geom.Compass;
import sitcov.geom.Vec2;
import sitcov.world.Dimensions;
import sitcov.world.Junction;
import sitcov.world.Layout;
import sitcov.world.ParkedCar;
import sitcov.world.Road;
import sitcov.world.SituationEdit;
import sitcov.world.StartPose;
import sitcov.world.WorldMap;

/**
 * The edits coverage search makes: one aimed at the next bin of one criterion, or one drawn at random.
 * An aim is worked out from the map's geometry alone; whether it lands in the cell it aims at is only
 * known once its map is measured, and an edit that lands elsewhere costs its candidate like any other.
 */
final class AimedEdits {
    /** A new branch is at least this long, and at most this much longer. */
    private static final double BRANCH_MIN = 25;
    private static final double BRANCH_SPREAD = 35;
    /** A branch made for the Target runs this far past it, clear of the dead end's square. */
    private static final double BEYOND_TARGET = 10;
    /**
     * A start or Target placed near a road's end stops at least this far short of it (a dead end's
     * square reaches 6 m in), and at most {@link #END_SPREAD} further.
     */
    private static final double END_MARGIN = 6.5;
    private static final double END_SPREAD = 3;
    /** Far-apart spots are drawn from this many nearest their corner, so that they land in many cells, not one. */
    private static final int NEAREST_SPOTS = 1;
    /** A lane's centre lies this far from its road's centre line. */
    private static final double LANE_OFFSET = Dimensions.LANE_WIDTH / 2;

    private AimedEdits() {
    }

    /**
     * An edit meant to move criterion {@code c} of {@code map} from bin {@code digit} one bin up or
     * down ({@code step} ±1), to a value drawn in that bin (at most 40 m into an open-ended one).
     */
    static SituationEdit toward(WorldMap map, GridDefinition grid, int c, int digit, int step, RandomGenerator choose) {
        Layout layout = map.layout();
        Bins bins = grid.bins().get(c);
        double lo = bins.lower(digit + step);
        double hi = Math.min(bins.upper(digit + step), lo + 40);
        double wanted = lo + choose.nextDouble() * (hi - lo);
        double sign = choose.nextBoolean() ? 1 : -1;
        return switch (grid.criteria().get(c)) {
            case TARGET_TO_OBSTACLE -> parkedCarAt(layout, wanted, step, sign, choose);
            case START_TO_TARGET -> {
                Optional<Vec2> start = layout.carStart().map(StartPose::position);
                List<SituationEdit> places = start.map(from -> switch (choose.nextInt(3)) {
                    case 0 -> targetsAtDistance(layout, from, wanted, choose);
                    case 1 -> targetsOnNewBranch(layout, from, wanted, choose);
                    default -> List.<SituationEdit>of();
                }).orElse(List.of());
                if (step > 0 && digit + step == bins.count() - 1 && choose.nextBoolean()) {
                    yield farApart(map, choose).orElseGet(() -> startMoved(sign, choose));
                }
                yield places.isEmpty() ? startMoved(sign, choose) : places.get(choose.nextInt(places.size()));
            }
            case PREVIOUS_JUNCTION_TO_TARGET -> junctionBehind(layout, wanted, step, choose)
                    .orElseGet(() -> new SituationEdit.MoveTarget(sign * (2 + choose.nextDouble() * 18)));
        };
    }

    /**
     * A parked car the wanted distance from the Target, along its road either way or in any direction;
     * or, going up, the nearest removed.
     */
    private static SituationEdit parkedCarAt(Layout layout, double wanted, int step, double sign, RandomGenerator choose) {
        Vec2 target = targetOf(layout);
        ParkedCar nearest = layout.parkedCars().stream()
                .min(Comparator.comparingDouble(p -> p.centre().distanceTo(target))).orElse(null);
        if (step > 0 && nearest != null && choose.nextBoolean()) {
            return new SituationEdit.RemoveParkedCar(nearest.id());
        }
        if (choose.nextBoolean()) {
            // in any direction: near a junction, whose approaches hold no parked car, only another road
            // passing close by (a parallel one, say) can hold the car the cell asks for
            double bearing = choose.nextDouble() * 2 * Math.PI;
            return new SituationEdit.AddParkedCar(target.x() + wanted * Math.cos(bearing), target.y() + wanted * Math.sin(bearing));
        }
        boolean alongX = layout.target().map(t -> !layout.roads().get(t.roadId()).isNorthSouth()).orElse(true);
        return alongX ? new SituationEdit.AddParkedCar(target.x() + sign * wanted, target.y())
                : new SituationEdit.AddParkedCar(target.x(), target.y() + sign * wanted);
    }

    private static SituationEdit startMoved(double sign, RandomGenerator choose) {
        return new SituationEdit.MoveStart(sign * (10 + choose.nextDouble() * 50));
    }

    /**
     * The previous junction brought to the wanted distance behind the Target (in its lane's direction
     * of travel): going down, a branch road added there or the Target moved back towards the junction it
     * has; going up, the Target moved on, or the branch road that makes the junction behind it removed.
     */
    private static Optional<SituationEdit> junctionBehind(Layout layout, double wanted, int step, RandomGenerator choose) {
        if (layout.target().isEmpty()) {
            return Optional.empty();
        }
        Road road = layout.roads().get(layout.target().get().roadId());
        Vec2 t = layout.target().get().position();
        Compass lane = road.laneDirectionAt(t.x(), t.y());
        double forward = road.isNorthSouth() ? lane.dy() : lane.dx();
        double along = road.along(t.x(), t.y());
        double offset = road.across(t.x(), t.y()) - road.centre();
        double behind = Math.sqrt(Math.max(0, wanted * wanted - offset * offset));
        Optional<Junction> previous = previousJunction(layout, road, t, lane);
        double now = previous.map(j -> Math.abs(road.along(j.centre().x(), j.centre().y()) - along)).orElse(Double.NaN);
        if (step < 0 && (previous.isEmpty() || choose.nextBoolean())) {
            double side = choose.nextBoolean() ? 1 : -1;
            return Optional.of(new SituationEdit.AddBranchRoad(road.id(), along - forward * behind,
                    side * (BRANCH_MIN + choose.nextDouble() * BRANCH_SPREAD)));
        }
        if (previous.isEmpty()) {
            return Optional.empty();
        }
        if (step > 0 && choose.nextBoolean()) {
            Vec2 centre = previous.get().centre();
            Optional<Road> branch = layout.roads().stream().filter(r -> r.id() != road.id())
                    .filter(r -> r.start().equals(centre) || r.end().equals(centre)).findFirst();
            if (branch.isPresent()) {
                return Optional.of(new SituationEdit.RemoveBranchRoad(branch.get().id()));
            }
        }
        return Optional.of(new SituationEdit.MoveTarget(forward * (behind - now)));
    }

    private static Optional<Junction> previousJunction(Layout layout, Road road, Vec2 t, Compass lane) {
        return layout.junctions().stream().filter(j -> road.carries(j.centre()))
                .filter(j -> (j.centre().x() - t.x()) * lane.dx() + (j.centre().y() - t.y()) * lane.dy() < 0)
                .min(Comparator.comparingDouble(j -> j.centre().distanceTo(t)));
    }

    /**
     * The start placed near one corner of the world and the Target near the opposite one, each at the
     * lane point nearest its corner, on an existing road or on a new branch from one to the world's
     * edge: a start 200 m or more from the Target needs the two within a few metres of opposite
     * corners of a 200 × 100 m world, which the generator's roads seldom reach.
     */
    private static Optional<SituationEdit> farApart(WorldMap map, RandomGenerator choose) {
        Vec2 from = new Vec2(choose.nextBoolean() ? 0 : Dimensions.WORLD_WIDTH, choose.nextBoolean() ? 0 : Dimensions.WORLD_HEIGHT);
        Vec2 to = new Vec2(Dimensions.WORLD_WIDTH - from.x(), Dimensions.WORLD_HEIGHT - from.y());
        Optional<Spot> start = nearest(map, from, choose);
        Optional<Spot> target = nearest(map, to, choose);
        if (start.isEmpty() || target.isEmpty()) {
            return Optional.empty();
        }
        List<SituationEdit> edits = new ArrayList<>();
        start.get().branch().ifPresent(edits::add);
        target.get().branch().ifPresent(edits::add);
        edits.add(new SituationEdit.PlaceStart(start.get().point().x(), start.get().point().y()));
        edits.add(new SituationEdit.PlaceTarget(target.get().point().x(), target.get().point().y()));
        return Optional.of(new SituationEdit.Chain(edits));
    }

    /** A lane point, on an existing road or on the branch road to be added first. */
    private record Spot(Vec2 point, Optional<SituationEdit> branch) {
    }

    /**
     * The lane point nearest {@code corner}: short of a road's end, or near the far end of a new branch
     * from a road, if that branch fits among the roads (the generator too draws a junction again until
     * its road fits).
     */
    private static Optional<Spot> nearest(WorldMap map, Vec2 corner, RandomGenerator choose) {
        Layout layout = map.layout();
        List<Spot> spots = new ArrayList<>();
        for (Road road : layout.roads()) {
            double margin = END_MARGIN + choose.nextDouble() * END_SPREAD;
            double side = Math.signum(road.across(corner.x(), corner.y()) - road.centre());
            double along = clamp(road.along(corner.x(), corner.y()), road.from() + margin, road.to() - margin);
            spots.add(new Spot(road.point(along, road.centre() + side * LANE_OFFSET), Optional.empty()));
            double at = clamp(road.along(corner.x(), corner.y()), road.from() + Dimensions.JUNCTION_END_MARGIN,
                    road.to() - Dimensions.JUNCTION_END_MARGIN);
            double length = road.across(corner.x(), corner.y()) - road.centre();
            if (Math.abs(length) >= Dimensions.MIN_ROAD_LENGTH && road.length() > 2 * Dimensions.JUNCTION_END_MARGIN) {
                Vec2 junction = road.point(at, road.centre());
                Road branch = Road.between(layout.roads().size(), junction, road.point(at, road.centre() + length));
                double end = length > 0 ? branch.to() - margin : branch.from() + margin;
                double lane = branch.centre() + Math.signum(road.along(corner.x(), corner.y()) - at) * LANE_OFFSET;
                spots.add(new Spot(branch.point(end, lane), Optional.of(new SituationEdit.AddBranchRoad(road.id(), at, length))));
            }
        }
        List<Spot> nearest = spots.stream().sorted(Comparator.comparingDouble(spot -> spot.point().distanceTo(corner)))
                .filter(spot -> spot.branch().map(b -> b.edit(map).isPresent()).orElse(true)).limit(NEAREST_SPOTS).toList();
        return nearest.isEmpty() ? Optional.empty() : Optional.of(nearest.get(choose.nextInt(nearest.size())));
    }

    private static double clamp(double v, double lo, double hi) {
        return Math.max(lo, Math.min(hi, v));
    }

    /** The Target placed {@code wanted} metres from {@code from}, in a lane of any road that passes at that distance. */
    private static List<SituationEdit> targetsAtDistance(Layout layout, Vec2 from, double wanted, RandomGenerator choose) {
        List<SituationEdit> places = new ArrayList<>();
        for (Road road : layout.roads()) {
            pointAtDistance(road, from, wanted, choose).ifPresent(p -> places.add(new SituationEdit.PlaceTarget(p.x(), p.y())));
        }
        return places;
    }

    /**
     * A branch road added and the Target placed on it {@code wanted} metres from {@code from}, where
     * no road passes: from each road, at a point drawn along it, towards the world's edge on each side.
     */
    private static List<SituationEdit> targetsOnNewBranch(Layout layout, Vec2 from, double wanted, RandomGenerator choose) {
        List<SituationEdit> places = new ArrayList<>();
        for (Road parent : layout.roads()) {
            double room = parent.length() - 2 * Dimensions.JUNCTION_END_MARGIN;
            if (room <= 0) {
                continue;
            }
            double along = parent.from() + Dimensions.JUNCTION_END_MARGIN + choose.nextDouble() * room;
            Vec2 centre = parent.point(along, parent.centre());
            for (double side : new double[] {-1, 1}) {
                Vec2 edge = parent.isNorthSouth()
                        ? new Vec2(side < 0 ? 0 : Dimensions.WORLD_WIDTH, centre.y())
                        : new Vec2(centre.x(), side < 0 ? 0 : Dimensions.WORLD_HEIGHT);
                if (edge.distanceTo(centre) < Dimensions.MIN_ROAD_LENGTH) {
                    continue;
                }
                Road branch = Road.between(layout.roads().size(), centre, edge);
                // only as long as the Target needs: a shorter branch meets fewer roads
                pointAtDistance(branch, from, wanted, choose).ifPresent(p -> places.add(new SituationEdit.Chain(List.of(
                        new SituationEdit.AddBranchRoad(parent.id(), along, side * Math.max(Dimensions.MIN_ROAD_LENGTH,
                                p.distanceTo(centre) + BEYOND_TARGET)),
                        new SituationEdit.PlaceTarget(p.x(), p.y())))));
            }
        }
        return places;
    }

    /** A point in a lane of {@code road} {@code wanted} metres from {@code from}: a root of |lane(t) − from| = wanted. */
    private static Optional<Vec2> pointAtDistance(Road road, Vec2 from, double wanted, RandomGenerator choose) {
        double across = road.centre() + (choose.nextBoolean() ? LANE_OFFSET : -LANE_OFFSET);
        Vec2 origin = road.point(0, across);
        double ex = road.isNorthSouth() ? 0 : 1;
        double ey = road.isNorthSouth() ? 1 : 0;
        double dx = origin.x() - from.x();
        double dy = origin.y() - from.y();
        double along = dx * ex + dy * ey;
        double discriminant = along * along - (dx * dx + dy * dy - wanted * wanted);
        if (discriminant < 0) {
            return Optional.empty();
        }
        double t = -along + (choose.nextBoolean() ? 1 : -1) * Math.sqrt(discriminant);
        return t < road.from() || t > road.to() ? Optional.empty() : Optional.of(road.point(t, across));
    }

    /** An edit drawn at random: the Target, the start or a parked car moved, a parked car or a branch road added or removed. */
    static SituationEdit random(Layout layout, RandomGenerator choose) {
        List<ParkedCar> cars = layout.parkedCars();
        int kind = choose.nextInt(7);
        double sign = choose.nextBoolean() ? 1 : -1;
        return switch (kind) {
            case 0 -> new SituationEdit.MoveTarget(sign * (1 + choose.nextDouble() * 29));
            case 1 -> new SituationEdit.MoveStart(sign * (5 + choose.nextDouble() * 55));
            case 5 -> {
                Road parent = layout.roads().get(choose.nextInt(layout.roads().size()));
                yield new SituationEdit.AddBranchRoad(parent.id(), parent.from() + choose.nextDouble() * parent.length(),
                        sign * (BRANCH_MIN + choose.nextDouble() * BRANCH_SPREAD));
            }
            case 6 -> new SituationEdit.RemoveBranchRoad(choose.nextInt(layout.roads().size()));
            default -> {
                if (kind == 2 || cars.isEmpty()) {
                    // a parked car near the Target (the first criterion measures how near the nearest is)
                    Vec2 t = targetOf(layout);
                    yield new SituationEdit.AddParkedCar(t.x() + (choose.nextDouble() - 0.5) * 40,
                            t.y() + (choose.nextDouble() - 0.5) * 40);
                }
                ParkedCar car = cars.get(choose.nextInt(cars.size()));
                yield kind == 3 ? new SituationEdit.RemoveParkedCar(car.id())
                        : new SituationEdit.MoveParkedCar(car.id(), sign * (1 + choose.nextDouble() * 14));
            }
        };
    }

    private static Vec2 targetOf(Layout layout) {
        return layout.target().map(t -> t.position()).orElse(new Vec2(Dimensions.WORLD_WIDTH / 2, Dimensions.WORLD_HEIGHT / 2));
    }
}
