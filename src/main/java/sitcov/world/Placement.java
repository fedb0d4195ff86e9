package sitcov.world;

import static sitcov.world.Dimensions.AUTONOMOUS_CAR_LENGTH;
import static sitcov.world.Dimensions.AUTONOMOUS_CAR_WIDTH;
import static sitcov.world.Dimensions.CAR_LENGTH;
import static sitcov.world.Dimensions.CAR_WIDTH;
import static sitcov.world.Dimensions.WORLD_HEIGHT;
import static sitcov.world.Dimensions.WORLD_WIDTH;
import static sitcov.world.Dimensions.rounded;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.random.RandomGenerator;
import sitcov.geom.Box;
import sitcov.geom.Vec2;

/**
 * Places what stands on the roads (the generator's steps after the road tree;
 * src/main/java/sitcov/cli/README.md, "Maps and situation files"): parked cars, the Target, the
 * autonomous car's start and the moving cars, each by bounded tries of uniform points. A point
 * found on the last try counts (the original's off-by-one is not kept).
 */
final class Placement {
    static final int PARKED_CAR_TRIES = 50;
    static final int MOVING_CAR_TRIES = 50;
    /** The original retried the Target and start without bound; a bound keeps generation total. */
    static final int TARGET_TRIES = 1000;
    static final int START_TRIES = 1000;
    /** Same-kerb parked cars may stand bumper to bumper; across the road they keep a car and a gap apart. */
    static final double SAME_KERB_SPACING = CAR_LENGTH;
    static final double OPPOSITE_KERB_SPACING = (CAR_LENGTH + 2) * 1.5;
    /** The Target is kept this far from parked cars, where the car could not come within capture distance. */
    static final double TARGET_CLEARANCE = 1.0;
    static final double MIN_START_TO_TARGET = 3.0;
    static final double MOVING_CAR_MIN_DISTANCE = 5.0;
    /** The car starts at least this far behind a parked car in its lane, room to pull out round it. */
    static final double ROOM_AHEAD = 8.0;

    private final RoadNetwork network;
    private final Draws draws;

    Placement(RoadNetwork network) {
        this(network, new Draws(Tilt.NOMINAL));
    }

    Placement(RoadNetwork network, Draws draws) {
        this.network = network;
        this.draws = draws;
    }

    Placed<ParkedCar> parkedCars(RandomGenerator random, List<Omission> omissions) {
        int count = draws.count(DrawSite.PARKED_CARS, random) + 5;
        List<ParkedCar> cars = new ArrayList<>();
        for (int k = 0; k < count; k++) {
            ParkedCar car = null;
            for (int t = 0; t < PARKED_CAR_TRIES && car == null; t++) {
                car = parkedCarAt(cars.size(), random.nextDouble() * WORLD_WIDTH, random.nextDouble() * WORLD_HEIGHT, cars);
            }
            if (car == null) {
                omissions.add(new Omission("parked car " + (k + 1) + " of " + count,
                        "no free kerbside place in " + PARKED_CAR_TRIES + " tries"));
            } else {
                cars.add(car);
            }
        }
        return new Placed<>(cars, count);
    }

    private ParkedCar parkedCarAt(int id, double x, double y, List<ParkedCar> others) {
        Road road = network.roadAt(x, y);
        if (road == null || network.isInJunction(x, y)) {
            return null;
        }
        Vec2 centre = RoadNetwork.kerbsidePosition(road, x, y);
        ParkedCar car = new ParkedCar(id, road.id(), centre, road.axis());
        Box footprint = car.footprint();
        if (!network.isOnRoad(footprint) || network.overlapsJunction(footprint)
                || network.isInJunctionZone(centre.x(), centre.y())) {
            return null;
        }
        for (ParkedCar other : others) {
            if (tooNear(road, car, other)) {
                return null;
            }
        }
        return car;
    }

    /**
     * Whether two parked cars on {@code road} stand nearer along it than the generator spaces them:
     * nose to tail at the same kerb, or staggered across it so closely that no car could pass between.
     */
    static boolean tooNear(Road road, ParkedCar car, ParkedCar other) {
        if (car.roadId() != road.id() || other.roadId() != road.id()) {
            return false;
        }
        double gap = Math.abs(road.along(other.centre().x(), other.centre().y()) - road.along(car.centre().x(), car.centre().y()));
        boolean sameKerb = road.across(other.centre().x(), other.centre().y()) == road.across(car.centre().x(), car.centre().y());
        return gap < (sameKerb ? SAME_KERB_SPACING : OPPOSITE_KERB_SPACING);
    }

    Optional<Target> target(RandomGenerator random, List<ParkedCar> parked, List<Omission> omissions) {
        for (int t = 0; t < TARGET_TRIES; t++) {
            double x = rounded(draws.coordinate(DrawSite.TARGET_X, random) * WORLD_WIDTH);
            double y = rounded(draws.coordinate(DrawSite.TARGET_Y, random) * WORLD_HEIGHT);
            Road road = network.roadAt(x, y);
            if (road != null && !network.isInJunction(x, y) && !nearParkedCar(x, y, parked, TARGET_CLEARANCE)) {
                return Optional.of(new Target(new Vec2(x, y), road.id()));
            }
        }
        omissions.add(new Omission("Target", "no free place on a road in " + TARGET_TRIES + " tries"));
        return Optional.empty();
    }

    Optional<StartPose> carStart(RandomGenerator random, List<ParkedCar> parked, Optional<Target> target,
                                 List<Omission> omissions) {
        for (int t = 0; t < START_TRIES; t++) {
            double x = draws.coordinate(DrawSite.START_X, random) * WORLD_WIDTH;
            double y = draws.coordinate(DrawSite.START_Y, random) * WORLD_HEIGHT;
            Optional<StartPose> pose = laneStart(x, y, parked, AUTONOMOUS_CAR_LENGTH, AUTONOMOUS_CAR_WIDTH);
            if (pose.isPresent() && target.map(g -> g.position().distanceTo(pose.get().position()) >= MIN_START_TO_TARGET)
                    .orElse(true) && hasRoomAhead(pose.get(), parked)) {
                return pose;
            }
        }
        omissions.add(new Omission("autonomous car", "no free lane start in " + START_TRIES + " tries"));
        return Optional.empty();
    }

    Placed<StartPose> movingCars(RandomGenerator random, List<ParkedCar> parked, Optional<StartPose> carStart,
                                 List<Omission> omissions) {
        int count = draws.count(DrawSite.MOVING_CARS, random) + 5;
        Box car = carStart.map(p -> p.footprint(AUTONOMOUS_CAR_LENGTH, AUTONOMOUS_CAR_WIDTH)).orElse(null);
        List<StartPose> placed = new ArrayList<>();
        List<Box> bodies = new ArrayList<>();
        for (int k = 0; k < count; k++) {
            StartPose found = null;
            for (int t = 0; t < MOVING_CAR_TRIES && found == null; t++) {
                double x = random.nextDouble() * WORLD_WIDTH;
                double y = random.nextDouble() * WORLD_HEIGHT;
                Optional<StartPose> pose = laneStart(x, y, parked, CAR_LENGTH, CAR_WIDTH);
                if (pose.isEmpty()) {
                    continue;
                }
                Box body = pose.get().footprint(CAR_LENGTH, CAR_WIDTH);
                boolean clear = (car == null || (!body.overlaps(car)
                        && carStart.get().position().distanceTo(pose.get().position()) >= MOVING_CAR_MIN_DISTANCE))
                        && bodies.stream().noneMatch(body::overlaps);
                if (clear) {
                    found = pose.get();
                    bodies.add(body);
                }
            }
            if (found == null) {
                omissions.add(new Omission("moving car " + (k + 1) + " of " + count,
                        "no free lane start in " + MOVING_CAR_TRIES + " tries"));
            } else {
                placed.add(found);
            }
        }
        return new Placed<>(placed, count);
    }

    /** Whether no parked car stands in the car's lane just ahead of its start, where it could not pull out round it. */
    static boolean hasRoomAhead(StartPose pose, List<ParkedCar> parked) {
        var ahead = pose.position().moved(pose.heading().bearing(), ROOM_AHEAD);
        Box room = Box.behind(ahead.x(), ahead.y(), pose.heading().bearing(), ROOM_AHEAD, AUTONOMOUS_CAR_WIDTH);
        return parked.stream().noneMatch(p -> p.footprint().overlaps(room));
    }

    /** A lane start near the point (x, y) whose footprint is on the road, outside junctions and parked cars. */
    private Optional<StartPose> laneStart(double x, double y, List<ParkedCar> parked, double length, double width) {
        if (network.isInJunction(x, y)) {
            return Optional.empty();
        }
        Optional<StartPose> pose = network.snapToLane(x, y);
        if (pose.isEmpty()) {
            return pose;
        }
        Box body = pose.get().footprint(length, width);
        if (!network.isOnRoad(body) || network.overlapsJunction(body)
                || parked.stream().anyMatch(p -> p.footprint().overlaps(body))) {
            return Optional.empty();
        }
        return pose;
    }

    static boolean nearParkedCar(double x, double y, List<ParkedCar> parked, double clearance) {
        for (ParkedCar car : parked) {
            Box grown = Box.centred(car.centre().x(), car.centre().y(), car.axis().bearing(),
                    CAR_LENGTH + 2 * clearance, CAR_WIDTH + 2 * clearance);
            if (grown.contains(x, y)) {
                return true;
            }
        }
        return false;
    }
}
