package sitcov.world;

import java.util.List;
import java.util.Optional;

/**
 * The static part of a situation, everything situation coverage needs: roads, junctions, parked
 * cars, the Target and the autonomous car's start. Generated from the external seed without
 * placing moving cars.
 *
 * @param seed                the external seed it was generated from (0 for a hand-built layout)
 * @param junctionAttempts    how many T-junctions the generator tried to add
 * @param parkedCarsRequested how many parked cars it tried to place
 * @param omissions           what could not be placed, and why
 */
public record Layout(long seed, List<Road> roads, List<Junction> junctions, List<ParkedCar> parkedCars,
                     Optional<Target> target, Optional<StartPose> carStart,
                     int junctionAttempts, int parkedCarsRequested, List<Omission> omissions) {
    public Layout {
        roads = List.copyOf(roads);
        junctions = List.copyOf(junctions);
        parkedCars = List.copyOf(parkedCars);
        omissions = List.copyOf(omissions);
    }

    /** Whether a car can be run on it: it has a Target and a start. */
    public boolean isRunnable() {
        return target.isPresent() && carStart.isPresent();
    }

    public long tJunctionCount() {
        return junctions.stream().filter(j -> !j.isDeadEnd()).count();
    }

    public long deadEndCount() {
        return junctions.stream().filter(Junction::isDeadEnd).count();
    }
}
