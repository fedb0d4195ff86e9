package sitcov.world;

import java.util.ArrayList;
import java.util.List;

/**
 * A whole situation: the static layout plus the start poses of the moving cars. Immutable; the
 * external seed alone fixes it, and a situation file describes it completely.
 */
public record WorldMap(Layout layout, List<StartPose> movingCars, int movingCarsRequested,
                       List<Omission> movingCarOmissions) {
    public WorldMap {
        movingCars = List.copyOf(movingCars);
        movingCarOmissions = List.copyOf(movingCarOmissions);
    }

    public long seed() {
        return layout.seed();
    }

    /** Everything the generator could not place, layout first. */
    public List<Omission> omissions() {
        List<Omission> all = new ArrayList<>(layout.omissions());
        all.addAll(movingCarOmissions);
        return all;
    }
}
