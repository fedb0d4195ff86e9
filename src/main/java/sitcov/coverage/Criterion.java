package sitcov.coverage;

import java.util.Locale;
import sitcov.geom.Compass;
import sitcov.geom.Vec2;
import sitcov.world.Junction;
import sitcov.world.Layout;
import sitcov.world.ParkedCar;
import sitcov.world.Road;
import sitcov.world.Target;

/**
 * The paper's three situation criteria (experiments/README.md, "Situation coverage"), measured on a layout in metres. A
 * missing element gives 200, the width of the world, as in the original.
 */
public enum Criterion {
    /** C1: from the Target to the centre of the nearest parked car. */
    TARGET_TO_OBSTACLE("target-obstacle"),
    /** C2: from the autonomous car's start to the Target. */
    START_TO_TARGET("start-target"),
    /** C3: from the junction before the Target, upstream in the Target's lane, to the Target. */
    PREVIOUS_JUNCTION_TO_TARGET("previous-junction-target");

    static final double MISSING = 200;

    private final String key;

    Criterion(String key) {
        this.key = key;
    }

    /** The name used in grid definition files and result tables. */
    public String key() {
        return key;
    }

    public static Criterion ofKey(String key) {
        for (Criterion c : values()) {
            if (c.key.equals(key.toLowerCase(Locale.ROOT))) {
                return c;
            }
        }
        throw new IllegalArgumentException("unknown criterion '" + key + "'; the criteria are target-obstacle,"
                + " start-target and previous-junction-target");
    }

    public double value(Layout layout) {
        if (layout.target().isEmpty()) {
            return MISSING;
        }
        Target target = layout.target().get();
        return switch (this) {
            case TARGET_TO_OBSTACLE -> nearestParkedCar(layout, target.position());
            case START_TO_TARGET -> layout.carStart().map(s -> s.position().distanceTo(target.position())).orElse(MISSING);
            case PREVIOUS_JUNCTION_TO_TARGET -> previousJunction(layout, target);
        };
    }

    private static double nearestParkedCar(Layout layout, Vec2 target) {
        double nearest = MISSING;
        for (ParkedCar p : layout.parkedCars()) {
            nearest = Math.min(nearest, p.centre().distanceTo(target));
        }
        return nearest;
    }

    private static double previousJunction(Layout layout, Target target) {
        Road road = layout.roads().get(target.roadId());
        Vec2 t = target.position();
        Compass lane = road.laneDirectionAt(t.x(), t.y());
        double nearest = MISSING;
        for (Junction j : layout.junctions()) {
            if (!road.carries(j.centre())) {
                continue;
            }
            // behind the Target for a car driving its lane
            double ahead = (j.centre().x() - t.x()) * lane.dx() + (j.centre().y() - t.y()) * lane.dy();
            if (ahead < 0) {
                nearest = Math.min(nearest, j.centre().distanceTo(t));
            }
        }
        return nearest;
    }
}
