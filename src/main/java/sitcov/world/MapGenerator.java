package sitcov.world;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import sitcov.engine.RandomStreams;

/**
 * Generates a map from an external seed, purely: the same seed always gives an equal map. Each
 * kind of element draws from its own named stream of the seed, so the layout that situation
 * coverage needs is generated without placing moving cars, and adding moving cars changes
 * nothing else.
 */
public final class MapGenerator {
    public static final String ROADS_STREAM = "map.roads";
    public static final String PARKED_CARS_STREAM = "map.parked-cars";
    public static final String TARGET_STREAM = "map.target";
    public static final String CAR_START_STREAM = "map.car-start";
    public static final String MOVING_CARS_STREAM = "map.moving-cars";

    private MapGenerator() {
    }

    /** The whole situation of {@code seed}: layout and moving cars. */
    public static WorldMap generate(long seed) {
        return withMovingCars(layout(seed));
    }

    /**
     * The situation of {@code seed} drawn with the key draws under {@code tilt} (the same as
     * {@link #generate(long)} under {@link Tilt#NOMINAL}), with their trace: its likelihood under
     * the generator and under the tilt.
     */
    public static TracedMap generate(long seed, Tilt tilt) {
        Draws draws = new Draws(tilt);
        WorldMap map = withMovingCars(layout(seed, draws), draws);
        return new TracedMap(map, draws.trace());
    }

    /** The static layout of {@code seed}, without moving cars (what coverage needs). */
    public static Layout layout(long seed) {
        return layout(seed, new Draws(Tilt.NOMINAL));
    }

    private static Layout layout(long seed, Draws draws) {
        RandomStreams streams = new RandomStreams(seed);
        RoadTreeBuilder tree = new RoadTreeBuilder(streams.stream(ROADS_STREAM), draws);
        List<Junction> junctions = tree.build();
        List<Omission> omissions = new ArrayList<>(tree.omissions());
        RoadNetwork network = new RoadNetwork(tree.roads(), junctions);
        Placement placement = new Placement(network, draws);
        Placed<ParkedCar> parked = placement.parkedCars(streams.stream(PARKED_CARS_STREAM), omissions);
        Optional<Target> target = placement.target(streams.stream(TARGET_STREAM), parked.items(), omissions);
        Optional<StartPose> start = placement.carStart(streams.stream(CAR_START_STREAM), parked.items(), target, omissions);
        return new Layout(seed, tree.roads(), junctions, parked.items(), target, start, tree.attempts(),
                parked.requested(), omissions);
    }

    /** Adds the moving cars of the layout's seed. */
    public static WorldMap withMovingCars(Layout layout) {
        return withMovingCars(layout, new Draws(Tilt.NOMINAL));
    }

    private static WorldMap withMovingCars(Layout layout, Draws draws) {
        RandomStreams streams = new RandomStreams(layout.seed());
        Placement placement = new Placement(RoadNetwork.of(layout), draws);
        List<Omission> omissions = new ArrayList<>();
        Placed<StartPose> moving = placement.movingCars(streams.stream(MOVING_CARS_STREAM), layout.parkedCars(),
                layout.carStart(), omissions);
        return new WorldMap(layout, moving.items(), moving.requested(), omissions);
    }
}
