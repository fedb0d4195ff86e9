package sitcov.world;

import static sitcov.world.Dimensions.APPROACH_LENGTH;
import static sitcov.world.Dimensions.HALF_ROAD;
import static sitcov.world.Dimensions.JUNCTION_END_MARGIN;
import static sitcov.world.Dimensions.JUNCTION_SIZE;
import static sitcov.world.Dimensions.MIN_ROAD_LENGTH;
import static sitcov.world.Dimensions.WORLD_HEIGHT;
import static sitcov.world.Dimensions.WORLD_WIDTH;
import static sitcov.world.Dimensions.rounded;

import java.util.ArrayList;
import java.util.List;
import java.util.random.RandomGenerator;
import sitcov.geom.Rect;
import sitcov.geom.Vec2;

/**
 * Grows the road tree of a map (the generator's first steps;
 * src/main/java/sitcov/cli/README.md, "Maps and situation files"): a first road, then T-junctions whose
 * branch roads touch only their parent, then a dead end at every free road end. All draws come
 * from the one stream it is given.
 */
final class RoadTreeBuilder {
    static final int MIN_JUNCTION_ATTEMPTS = 5;
    static final int JUNCTION_ATTEMPT_SPREAD = 20;
    static final int ROAD_PICKS = 10;
    static final int OFFSET_TRIES = 10;
    static final int BRANCH_TRIES = 20;
    /** Free space kept around a branch road against every road but its parent, so parallel roads never merge. */
    static final double ROAD_CLEARANCE = 1.0;
    private static final int FIRST_ROAD_TRIES = 1000;

    private final RandomGenerator random;
    private final Draws draws;
    private final List<Road> roads = new ArrayList<>();
    private final List<Vec2> tJunctions = new ArrayList<>();
    private final List<Omission> omissions = new ArrayList<>();
    private int attempts;

    RoadTreeBuilder(RandomGenerator random, Draws draws) {
        this.random = random;
        this.draws = draws;
    }

    List<Road> roads() {
        return roads;
    }

    List<Omission> omissions() {
        return omissions;
    }

    int attempts() {
        return attempts;
    }

    /** Builds the tree and returns its junctions: T-junctions first, then dead ends. */
    List<Junction> build() {
        attempts = draws.count(DrawSite.JUNCTION_ATTEMPTS, random) + MIN_JUNCTION_ATTEMPTS;
        roads.add(firstRoad());
        for (int i = 1; i <= attempts; i++) {
            tryJunction(i);
        }
        List<Junction> junctions = new ArrayList<>();
        for (Vec2 centre : tJunctions) {
            junctions.add(withArms(junctions.size(), centre, roads));
        }
        for (Road road : roads) {
            for (Vec2 end : List.of(road.start(), road.end())) {
                if (junctions.stream().noneMatch(j -> j.contains(end.x(), end.y()))) {
                    junctions.add(withArms(junctions.size(), deadEndCentre(road, end), roads));
                }
            }
        }
        return junctions;
    }

    /** The centre of the dead end that closes {@code road} at its end {@code end}: half a road width inside. */
    static Vec2 deadEndCentre(Road road, Vec2 end) {
        Vec2 inside = road.point(road.along(end.x(), end.y()) == road.from()
                ? road.from() + HALF_ROAD : road.to() - HALF_ROAD, road.centre());
        return new Vec2(rounded(inside.x()), rounded(inside.y()));
    }

    private Road firstRoad() {
        double x = rounded(random.nextDouble() * (WORLD_WIDTH - 2 * HALF_ROAD) + HALF_ROAD);
        double y = rounded(random.nextDouble() * (WORLD_HEIGHT - 2 * HALF_ROAD) + HALF_ROAD);
        Axis axis = random.nextBoolean() ? Axis.EAST_WEST : Axis.NORTH_SOUTH;
        Vec2 start = new Vec2(x, y);
        for (int t = 0; t < FIRST_ROAD_TRIES; t++) {
            int sign = random.nextBoolean() ? -1 : 1;
            Vec2 end = endOf(start, axis, sign * random.nextDouble());
            if (start.distanceTo(end) >= MIN_ROAD_LENGTH) {
                return Road.between(0, start, end);
            }
        }
        throw new IllegalStateException("no first road of " + MIN_ROAD_LENGTH + " m in " + FIRST_ROAD_TRIES + " tries");
    }

    private void tryJunction(int attempt) {
        Road parent = null;
        Vec2 centre = null;
        for (int pick = 0; pick < ROAD_PICKS && centre == null; pick++) {
            parent = roads.get(random.nextInt(roads.size()));
            centre = freeJunctionPlace(parent);
        }
        if (centre == null) {
            omissions.add(new Omission("T-junction attempt " + attempt,
                    "no free place on a road in " + ROAD_PICKS + " roads x " + OFFSET_TRIES + " offsets"));
            return;
        }
        Axis axis = parent.axis().other();
        int direction = random.nextBoolean() ? -1 : 1;
        for (int t = 0; t < BRANCH_TRIES; t++) {
            if (t == BRANCH_TRIES / 2) {
                direction = -direction;
            }
            Vec2 end = endOf(centre, axis, direction * random.nextDouble());
            if (centre.distanceTo(end) < MIN_ROAD_LENGTH) {
                continue;
            }
            Road branch = Road.between(roads.size(), centre, end);
            if (isClearOfAllBut(branch, parent, roads)) {
                roads.add(branch);
                tJunctions.add(centre);
                return;
            }
        }
        omissions.add(new Omission("T-junction attempt " + attempt,
                "no branch road of " + (int) MIN_ROAD_LENGTH + " m clear of other roads in " + BRANCH_TRIES + " tries"));
    }

    /** A junction centre on {@code road}, at least 9 m from its ends, whose square meets no other; or null. */
    private Vec2 freeJunctionPlace(Road road) {
        double limit = (road.isNorthSouth() ? WORLD_HEIGHT : WORLD_WIDTH) - JUNCTION_SIZE;
        for (int t = 0; t < OFFSET_TRIES; t++) {
            double along = rounded(road.from() + random.nextDouble() * (road.length() - 2 * JUNCTION_END_MARGIN)
                    + JUNCTION_END_MARGIN);
            if (along >= limit || along - road.from() < JUNCTION_END_MARGIN || road.to() - along < JUNCTION_END_MARGIN) {
                continue;
            }
            Vec2 centre = road.point(along, road.centre());
            Rect square = Rect.square(centre.x(), centre.y(), JUNCTION_SIZE);
            if (tJunctions.stream().noneMatch(j -> Rect.square(j.x(), j.y(), JUNCTION_SIZE).overlaps(square))) {
                return centre;
            }
        }
        return null;
    }

    /** Whether {@code branch} keeps {@link #ROAD_CLEARANCE} from every road of {@code roads} but its parent. */
    static boolean isClearOfAllBut(Road branch, Road parent, List<Road> roads) {
        Rect surface = branch.surface().expanded(ROAD_CLEARANCE);
        for (Road road : roads) {
            if (road != parent && road.surface().touches(surface)) {
                return false;
            }
        }
        return true;
    }

    /** The end of a road from {@code start} along {@code axis}, {@code fraction} of the world across, kept on the map. */
    static Vec2 endOf(Vec2 start, Axis axis, double fraction) {
        if (axis == Axis.EAST_WEST) {
            return new Vec2(rounded(clamp(start.x() + fraction * WORLD_WIDTH, WORLD_WIDTH)), start.y());
        }
        return new Vec2(start.x(), rounded(clamp(start.y() + fraction * WORLD_HEIGHT, WORLD_HEIGHT)));
    }

    private static double clamp(double v, double max) {
        return Math.max(0, Math.min(max, v));
    }

    /** Road reaching no further than the square's own edge is no arm (the closed end of a dead end). */
    private static double armLength(double reach) {
        return reach > HALF_ROAD + 1e-6 ? Math.min(reach, APPROACH_LENGTH) : 0;
    }

    /** A junction at {@code centre} whose arms reach along every road through it, capped at 23 m. */
    static Junction withArms(int id, Vec2 centre, List<Road> roads) {
        double[] arms = new double[4]; // N, E, S, W
        for (Road road : roads) {
            if (!road.carries(centre)) {
                continue;
            }
            double along = road.along(centre.x(), centre.y());
            double before = armLength(along - road.from());
            double after = armLength(road.to() - along);
            if (road.isNorthSouth()) {
                arms[0] = Math.max(arms[0], before);
                arms[2] = Math.max(arms[2], after);
            } else {
                arms[3] = Math.max(arms[3], before);
                arms[1] = Math.max(arms[1], after);
            }
        }
        return new Junction(id, centre, rounded(arms[0]), rounded(arms[1]), rounded(arms[2]), rounded(arms[3]));
    }
}
