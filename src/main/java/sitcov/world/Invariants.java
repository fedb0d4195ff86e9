package sitcov.world;

import static sitcov.world.Dimensions.AUTONOMOUS_CAR_LENGTH;
import static sitcov.world.Dimensions.AUTONOMOUS_CAR_WIDTH;
import static sitcov.world.Dimensions.CAR_LENGTH;
import static sitcov.world.Dimensions.CAR_WIDTH;
import static sitcov.world.Dimensions.MIN_ROAD_LENGTH;
import static sitcov.world.Dimensions.WORLD_HEIGHT;
import static sitcov.world.Dimensions.WORLD_WIDTH;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.List;
import java.util.Optional;
import java.util.stream.Stream;
import sitcov.geom.Box;
import sitcov.geom.Compass;
import sitcov.geom.Rect;
import sitcov.geom.Vec2;

/**
 * The rules every generated map keeps (src/main/java/sitcov/cli/README.md, "Maps and situation files"). {@link
 * #check} lists each broken rule with the
 * element that breaks it; an empty list means the map is well formed.
 */
public final class Invariants {
    /** The kinds of element a rule is about; {@code NETWORK} is the road network as a whole. */
    public enum Element { ROAD, JUNCTION, PARKED_CAR, TARGET, CAR_START, MOVING_CAR, NETWORK }

    /** A broken rule: the element (kind and id, or 0 for the Target, the car start and the network) and the rule in words. */
    public record Violation(Element element, int index, String rule) {
        @Override
        public String toString() {
            return rule;
        }
    }

    private static final Rect WORLD = new Rect(0, 0, WORLD_WIDTH, WORLD_HEIGHT);
    private static final double EPS = 1e-6;

    private Invariants() {
    }

    /** The broken rules, in words. */
    public static List<String> violations(WorldMap map) {
        return check(map).stream().map(Violation::rule).toList();
    }

    public static List<String> violations(Layout layout) {
        return check(layout).stream().map(Violation::rule).toList();
    }

    public static List<Violation> check(WorldMap map) {
        List<Violation> v = new ArrayList<>(check(map.layout()));
        Layout layout = map.layout();
        RoadNetwork network = RoadNetwork.of(layout);
        List<Box> bodies = new ArrayList<>();
        layout.carStart().ifPresent(s -> bodies.add(s.footprint(AUTONOMOUS_CAR_LENGTH, AUTONOMOUS_CAR_WIDTH)));
        for (int i = 0; i < map.movingCars().size(); i++) {
            StartPose pose = map.movingCars().get(i);
            String name = "moving car " + i;
            checkStart(v, Element.MOVING_CAR, i, name, pose, CAR_LENGTH, CAR_WIDTH, layout, network);
            Box body = pose.footprint(CAR_LENGTH, CAR_WIDTH);
            if (layout.carStart().map(s -> s.position().distanceTo(pose.position()) < Placement.MOVING_CAR_MIN_DISTANCE)
                    .orElse(false)) {
                v.add(new Violation(Element.MOVING_CAR, i, name + " starts within " + Placement.MOVING_CAR_MIN_DISTANCE
                        + " m of the autonomous car"));
            }
            if (bodies.stream().anyMatch(body::overlaps)) {
                v.add(new Violation(Element.MOVING_CAR, i, name + " overlaps the autonomous car or another moving car"));
            }
            bodies.add(body);
        }
        return v;
    }

    public static List<Violation> check(Layout layout) {
        List<Violation> v = new ArrayList<>();
        RoadNetwork network = RoadNetwork.of(layout);
        checkRoads(v, layout.roads());
        checkJunctions(v, layout);
        checkParkedCars(v, layout, network);
        layout.target().ifPresent(t -> {
            Vec2 p = t.position();
            if (!network.isOnRoad(p.x(), p.y())) {
                v.add(new Violation(Element.TARGET, 0, "the Target " + p + " is off the road"));
            }
            if (network.isInJunction(p.x(), p.y())) {
                v.add(new Violation(Element.TARGET, 0, "the Target " + p + " is in a junction"));
            }
            misnamedRoad(layout, network, t.roadId(), p).ifPresent(actual -> v.add(new Violation(Element.TARGET, 0,
                    "the Target at " + at(p) + " names road " + t.roadId() + " but stands on road " + actual.id()
                            + ": set its ROAD_ID to " + actual.id())));
            if (layout.parkedCars().stream().anyMatch(c -> c.footprint().contains(p.x(), p.y()))) {
                v.add(new Violation(Element.TARGET, 0, "the Target " + p + " is inside a parked car"));
            } else if (Placement.nearParkedCar(p.x(), p.y(), layout.parkedCars(), Placement.TARGET_CLEARANCE)) {
                // the generator's clearance: nearer, the car could not come within capture distance
                v.add(new Violation(Element.TARGET, 0, "the Target " + p + " is within " + Placement.TARGET_CLEARANCE
                        + " m of a parked car"));
            }
        });
        layout.carStart().ifPresent(s -> {
            checkStart(v, Element.CAR_START, 0, "the autonomous car", s, AUTONOMOUS_CAR_LENGTH, AUTONOMOUS_CAR_WIDTH,
                    layout, network);
            if (layout.target().map(t -> t.position().distanceTo(s.position()) < Placement.MIN_START_TO_TARGET).orElse(false)) {
                v.add(new Violation(Element.CAR_START, 0, "the autonomous car starts within " + Placement.MIN_START_TO_TARGET
                        + " m of the Target: " + s));
            }
            if (!Placement.hasRoomAhead(s, layout.parkedCars())) {
                v.add(new Violation(Element.CAR_START, 0, "the autonomous car starts within " + Placement.ROOM_AHEAD
                        + " m behind a parked car: " + s));
            }
        });
        return v;
    }

    private static void checkRoads(List<Violation> v, List<Road> roads) {
        for (Road road : roads) {
            if (!WORLD.contains(road.surface())) {
                v.add(new Violation(Element.ROAD, road.id(), "road " + road.id() + " leaves the " + WORLD_WIDTH + " x "
                        + WORLD_HEIGHT + " m world: " + road.surface()));
            }
            if (road.length() < MIN_ROAD_LENGTH - EPS) {
                v.add(new Violation(Element.ROAD, road.id(), "road " + road.id() + " is " + road.length()
                        + " m, shorter than " + MIN_ROAD_LENGTH));
            }
        }
        // The network is a tree: roads meeting roads form a connected graph with one edge fewer than roads.
        int edges = 0;
        List<List<Integer>> next = new ArrayList<>();
        roads.forEach(r -> next.add(new ArrayList<>()));
        for (int a = 0; a < roads.size(); a++) {
            for (int b = a + 1; b < roads.size(); b++) {
                if (roads.get(a).surface().touches(roads.get(b).surface())) {
                    edges++;
                    next.get(a).add(b);
                    next.get(b).add(a);
                }
            }
        }
        boolean[] seen = new boolean[roads.size()];
        Deque<Integer> todo = new ArrayDeque<>(List.of(0));
        int reached = 0;
        while (!roads.isEmpty() && !todo.isEmpty()) {
            int r = todo.pop();
            if (!seen[r]) {
                seen[r] = true;
                reached++;
                next.get(r).forEach(todo::push);
            }
        }
        if (reached != roads.size() || edges != roads.size() - 1) {
            v.add(new Violation(Element.NETWORK, 0, "the roads are not a tree: " + roads.size() + " roads, " + edges
                    + " meetings, " + reached + " connected"));
        }
    }

    private static void checkJunctions(List<Violation> v, Layout layout) {
        List<Junction> junctions = layout.junctions();
        for (int a = 0; a < junctions.size(); a++) {
            Junction j = junctions.get(a);
            long carriers = layout.roads().stream().filter(r -> r.carries(j.centre())).count();
            int arms = j.arms().size();
            if (!(arms == 1 && carriers == 1) && !(arms == 3 && carriers == 2)) {
                v.add(new Violation(Element.JUNCTION, j.id(), "junction " + j.id() + " has " + arms + " arms on " + carriers
                        + " roads (a dead end has 1 arm on 1 road, a T-junction 3 arms on 2)"));
            } else {
                // the arms are written down, but the roads fix them: a shorter one would shrink the approach
                // zone where no parked car may stand, a longer one widen it
                Junction reach = RoadTreeBuilder.withArms(j.id(), j.centre(), layout.roads());
                if (Stream.of(Compass.values()).anyMatch(c -> Math.abs(j.arm(c) - reach.arm(c)) > EPS)) {
                    v.add(new Violation(Element.JUNCTION, j.id(), "junction " + j.id() + " has arms " + armsOf(j)
                            + " but its roads reach " + armsOf(reach) + " from its centre (capped at "
                            + Dimensions.APPROACH_LENGTH + " m): set ARM_NORTH ARM_EAST ARM_SOUTH ARM_WEST to "
                            + reach.armNorth() + " " + reach.armEast() + " " + reach.armSouth() + " " + reach.armWest()));
                }
            }
            for (int b = a + 1; b < junctions.size(); b++) {
                if (j.square().overlaps(junctions.get(b).square())) {
                    v.add(new Violation(Element.JUNCTION, junctions.get(b).id(), "junctions " + j.id() + " and "
                            + junctions.get(b).id() + " overlap"));
                }
            }
        }
        for (Road road : layout.roads()) {
            for (Vec2 end : List.of(road.start(), road.end())) {
                if (junctions.stream().noneMatch(j -> j.contains(end.x(), end.y()))) {
                    v.add(new Violation(Element.ROAD, road.id(), "road " + road.id() + " ends at " + end
                            + " with no junction or dead end"));
                }
            }
        }
    }

    private static void checkParkedCars(List<Violation> v, Layout layout, RoadNetwork network) {
        List<ParkedCar> cars = layout.parkedCars();
        List<Road> own = new ArrayList<>(cars.size());
        for (ParkedCar car : cars) {
            Box body = car.footprint();
            if (!network.isOnRoad(body)) {
                v.add(new Violation(Element.PARKED_CAR, car.id(), "parked car " + car.id() + " is not wholly on the road"));
            }
            Optional<Road> misnamed = misnamedRoad(layout, network, car.roadId(), car.centre());
            misnamed.ifPresent(actual -> v.add(new Violation(Element.PARKED_CAR, car.id(), "parked car " + car.id()
                    + " at " + at(car.centre()) + " names road " + car.roadId() + " but stands on road " + actual.id()
                    + ": set its ROAD_ID to " + actual.id())));
            Road road = misnamed.isEmpty() && car.roadId() >= 0 && car.roadId() < layout.roads().size() ? layout.roads().get(car.roadId()) : null;
            if (road != null && road.contains(car.centre().x(), car.centre().y()) && car.axis() != road.axis()) {
                v.add(new Violation(Element.PARKED_CAR, car.id(), "parked car " + car.id() + " lies " + car.axis()
                        + " on road " + road.id() + ", which runs " + road.axis() + ": set its AXIS to " + road.axis()));
            }
            // the spacing below is measured along the car's road: only a car on the road it names has one
            own.add(misnamed.isEmpty() ? road : null);
            if (network.overlapsJunction(body) || network.isInJunctionZone(car.centre().x(), car.centre().y())) {
                v.add(new Violation(Element.PARKED_CAR, car.id(), "parked car " + car.id()
                        + " is in a junction square, or centred in an approach or exit zone"));
            }
        }
        for (int a = 0; a < cars.size(); a++) {
            ParkedCar car = cars.get(a);
            for (int b = a + 1; b < cars.size(); b++) {
                ParkedCar other = cars.get(b);
                if (car.footprint().overlaps(other.footprint())) {
                    v.add(new Violation(Element.PARKED_CAR, other.id(), "parked cars " + car.id() + " and "
                            + other.id() + " overlap"));
                } else if (own.get(a) != null && own.get(b) != null && Placement.tooNear(own.get(a), car, other)) {
                    // the generator's spacing: staggered nearer across a road, they block it for good
                    v.add(new Violation(Element.PARKED_CAR, other.id(), "parked cars " + car.id() + " and " + other.id()
                            + " stand nearer along their road than the generator spaces them"));
                }
            }
        }
    }

    /**
     * The road a point stands on when it is not the road {@code roadId} names; empty when the named road
     * holds it, or when no road does (that is a rule of its own).
     */
    private static Optional<Road> misnamedRoad(Layout layout, RoadNetwork network, int roadId, Vec2 p) {
        boolean named = roadId >= 0 && roadId < layout.roads().size() && layout.roads().get(roadId).contains(p.x(), p.y());
        return named ? Optional.empty() : Optional.ofNullable(network.roadAt(p.x(), p.y()));
    }

    private static String at(Vec2 p) {
        return "(" + p.x() + ", " + p.y() + ")";
    }

    private static String armsOf(Junction j) {
        return "N " + j.armNorth() + ", E " + j.armEast() + ", S " + j.armSouth() + ", W " + j.armWest();
    }

    private static void checkStart(List<Violation> v, Element element, int index, String name, StartPose pose,
                                   double length, double width, Layout layout, RoadNetwork network) {
        Vec2 p = pose.position();
        boolean onLaneCentre = layout.roads().stream().anyMatch(road -> road.contains(p.x(), p.y())
                && Axis.of(pose.heading()) == road.axis()
                && Math.abs(road.across(p.x(), p.y()) - road.laneCentre(pose.heading())) <= EPS);
        if (!onLaneCentre) {
            v.add(new Violation(element, index, name + " does not start on a lane centre facing its legal direction: " + pose));
        }
        Box body = pose.footprint(length, width);
        if (!network.isOnRoad(body)) {
            v.add(new Violation(element, index, name + " does not start wholly on the road: " + pose));
        }
        if (network.overlapsJunction(body)) {
            v.add(new Violation(element, index, name + " starts in a junction: " + pose));
        }
        if (layout.parkedCars().stream().anyMatch(c -> c.footprint().overlaps(body))) {
            v.add(new Violation(element, index, name + " starts overlapping a parked car: " + pose));
        }
    }
}
