package sitcov.builtin;

import java.util.Arrays;
import java.util.List;
import sitcov.geom.Compass;
import sitcov.geom.Vec2;
import sitcov.world.Junction;
import sitcov.world.Road;
import sitcov.world.RoadNetwork;
import sitcov.world.Target;

/**
 * How far the Target is along the roads from each way out of each junction, arriving in the
 * Target's lane: the car's sat-nav. The car still picks exits by the paper's rule (exits not yet
 * taken first, then the one closest to the Target); "closest" is measured here along the roads
 * rather than as the crow flies, because on a tree of roads the straight-line choice leads into
 * branches that end far from the Target and a car could spend its whole run exploring them.
 */
final class Route {
    /** Extra metres charged for turning round in a junction, so a U-turn is chosen only when it saves that much. */
    static final double U_TURN_COST = 20;

    private double[][] toTarget;

    private Route(double[][] toTarget) {
        this.toTarget = toTarget;
    }

    /** Metres along the roads from leaving {@code junction} by {@code exit} to the Target; infinite if unreachable. */
    double distance(Junction junction, Compass exit) {
        return toTarget[junction.id()][exit.ordinal()];
    }

    static Route plan(RoadNetwork network, Target target) {
        List<Junction> junctions = network.junctions();
        int n = junctions.size();
        int[][] next = new int[n][4];
        double[][] length = new double[n][4];
        double[][] cost = new double[n][4];
        for (Junction j : junctions) {
            Arrays.fill(next[j.id()], -1);
            Arrays.fill(cost[j.id()], Double.POSITIVE_INFINITY);
            for (Compass c : j.arms()) {
                Junction neighbour = neighbour(network, j, c);
                if (neighbour != null) {
                    next[j.id()][c.ordinal()] = neighbour.id();
                    length[j.id()][c.ordinal()] = j.centre().distanceTo(neighbour.centre());
                }
                double reach = alongToTarget(network, j, c, target, neighbour);
                if (reach >= 0) {
                    cost[j.id()][c.ordinal()] = reach;
                }
            }
        }
        // Bellman–Ford relaxation: a few dozen junctions, so simplicity beats a priority queue
        boolean changed = true;
        for (int round = 0; changed && round <= 4 * n; round++) {
            changed = false;
            for (Junction j : junctions) {
                for (Compass c : j.arms()) {
                    int k = next[j.id()][c.ordinal()];
                    if (k < 0) {
                        continue;
                    }
                    Compass arrival = c.opposite();
                    double best = Double.POSITIVE_INFINITY;
                    for (Compass out : junctions.get(k).arms()) {
                        double turn = out == arrival ? U_TURN_COST : 0;
                        best = Math.min(best, cost[k][out.ordinal()] + turn);
                    }
                    double through = length[j.id()][c.ordinal()] + best;
                    if (through < cost[j.id()][c.ordinal()] - 1e-9) {
                        cost[j.id()][c.ordinal()] = through;
                        changed = true;
                    }
                }
            }
        }
        return new Route(cost);
    }

    /** The nearest junction reached by leaving {@code from} along arm {@code c}, or null. */
    private static Junction neighbour(RoadNetwork network, Junction from, Compass c) {
        Junction nearest = null;
        double best = Double.POSITIVE_INFINITY;
        for (Road road : network.roads()) {
            if (road.isNorthSouth() != c.isNorthSouth() || !road.carries(from.centre())) {
                continue;
            }
            for (Junction j : network.junctions()) {
                if (j == from || !road.carries(j.centre()) || !j.hasArm(c.opposite())) {
                    continue;
                }
                double ahead = (j.centre().x() - from.centre().x()) * c.dx() + (j.centre().y() - from.centre().y()) * c.dy();
                if (ahead > 0 && ahead < best) {
                    best = ahead;
                    nearest = j;
                }
            }
        }
        return nearest;
    }

    /**
     * Metres from leaving {@code from} by {@code c} to the Target, when the Target lies on that
     * stretch of road in the lane heading {@code c}; otherwise −1.
     */
    private static double alongToTarget(RoadNetwork network, Junction from, Compass c, Target target, Junction to) {
        Road road = network.roads().get(target.roadId());
        if (road.isNorthSouth() != c.isNorthSouth() || !road.carries(from.centre())) {
            return -1;
        }
        Vec2 t = target.position();
        if (road.laneDirectionAt(t.x(), t.y()) != c) {
            return -1;
        }
        double ahead = (t.x() - from.centre().x()) * c.dx() + (t.y() - from.centre().y()) * c.dy();
        double limit = to == null ? Double.POSITIVE_INFINITY : from.centre().distanceTo(to.centre());
        return ahead > 0 && ahead < limit ? ahead : -1;
    }
}
