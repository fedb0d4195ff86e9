package sitcov.world;

import java.util.List;
import java.util.Locale;

/** A one-paragraph account of a map in words: what it holds and what the generator had to leave out. */
public final class MapDescription {
    private MapDescription() {
    }

    public static String of(WorldMap map) {
        Layout l = map.layout();
        StringBuilder s = new StringBuilder();
        s.append(String.format(Locale.ROOT, "Map of seed %d: %d roads, %d junctions (%d T-junctions of %d attempted, "
                        + "%d dead ends), %d of %d parked cars, %d of %d moving cars.",
                l.seed(), l.roads().size(), l.junctions().size(), l.tJunctionCount(), l.junctionAttempts(),
                l.deadEndCount(), l.parkedCars().size(), l.parkedCarsRequested(), map.movingCars().size(),
                map.movingCarsRequested()));
        if (l.target().isPresent() && l.carStart().isPresent()) {
            Target t = l.target().get();
            StartPose start = l.carStart().get();
            s.append(String.format(Locale.ROOT, " The autonomous car starts at (%.1f, %.1f) heading %s, %.1f m "
                            + "from the Target at (%.1f, %.1f) on road %d.",
                    start.position().x(), start.position().y(), start.heading().name().toLowerCase(Locale.ROOT),
                    start.position().distanceTo(t.position()), t.position().x(), t.position().y(), t.roadId()));
        } else {
            s.append(" It cannot be run: it has no ").append(l.target().isEmpty() ? "Target" : "start for the car").append('.');
        }
        List<Omission> omitted = map.omissions();
        if (omitted.isEmpty()) {
            s.append(" Nothing was omitted.");
        } else {
            s.append(" Omitted: ");
            for (int i = 0; i < omitted.size(); i++) {
                s.append(i == 0 ? "" : "; ").append(omitted.get(i));
            }
            s.append('.');
        }
        return s.toString();
    }
}
