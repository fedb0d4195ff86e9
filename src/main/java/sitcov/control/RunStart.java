package sitcov.control;

import java.util.function.LongSupplier;
import sitcov.engine.RandomStreams;
import sitcov.world.WorldMap;

/**
 * What a controller is told when a run starts: the map (its roads, Target and the car's start; the
 * parked cars and moving cars are for its sensors to find), the run's seeds, the run's named random
 * streams (a controller's own random choices come from a stream of its own name) and the run's clock.
 */
public record RunStart(WorldMap map, long internalSeed, RandomStreams streams, LongSupplier clock) {
}
