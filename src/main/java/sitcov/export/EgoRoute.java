package sitcov.export;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import sitcov.geom.Compass;
import sitcov.geom.Vec2;
import sitcov.world.Dimensions;
import sitcov.world.Junction;
import sitcov.world.Road;
import sitcov.world.RoadNetwork;
import sitcov.world.StartPose;
import sitcov.world.Target;

/**
 * The route a situation gives the car under test: from its start along the lanes to the Target, turning round
 * as few times as it can (on the spot at a dead end, or in a junction, as sitcov's cars do), and the shortest such
 * route. The roads form a tree, so a Target behind the car, or in the lane heading away from it, is reached only by
 * turning round somewhere; OpenDRIVE has no lane that turns round, so a player that plans from the roads alone
 * finds no way there. The waypoints say where to go.
 *
 * @param waypoints points on lane centres in driving order, each heading the way its lane carries traffic: the
 *                  start, the middle of each stretch it drives (from the start, between junctions, to the
 *                  Target), and the Target's place along its lane; a route that turns round before it leaves the
 *                  car's road begins after the turn
 */
record EgoRoute(List<Waypoint> waypoints) {
    /** How far a junction's square reaches from its centre along a road. */
    private static final double SQUARE = Dimensions.JUNCTION_SIZE / 2;

    /** A point on a lane centre and the way the lane carries traffic there. */
    record Waypoint(Vec2 point, Compass heading) {
    }

    /** Leaving a junction by one of its arms: a state of the search. */
    private record Exit(Junction junction, Compass arm) {
        int index() {
            return junction.id() * 4 + arm.ordinal();
        }
    }

    /** What reaching a state costs: the turns round first, then the metres. */
    private record Cost(int turns, double metres) {
        boolean below(Cost o) {
            return turns < o.turns || (turns == o.turns && metres < o.metres - 1e-9);
        }

        Cost then(boolean turnRound, double more) {
            return new Cost(turns + (turnRound ? 1 : 0), metres + more);
        }
    }

    /** The route, or empty when none reaches the Target (a map edited by hand can leave it unreachable). */
    static Optional<EgoRoute> plan(RoadNetwork network, StartPose start, Target target) {
        Road road = network.roads().get(target.roadId());
        Vec2 t = target.position();
        Compass lane = road.laneDirectionAt(t.x(), t.y());
        Waypoint goal = new Waypoint(road.point(road.along(t.x(), t.y()), road.laneCentre(lane)), lane);
        Waypoint from = new Waypoint(start.position(), start.heading());
        if (goalNext(network, from, road, goal)) {
            return Optional.of(new EgoRoute(List.of(from, goal)));
        }
        Junction first = junctionNext(network, from);
        List<Junction> junctions = network.junctions();
        Cost[] cost = new Cost[junctions.size() * 4];
        Exit[] previous = new Exit[cost.length];
        boolean[] settled = new boolean[cost.length];
        for (Compass arm : first == null ? List.<Compass>of() : first.arms()) {
            cost[new Exit(first, arm).index()] = new Cost(0, 0)
                    .then(arm == start.heading().opposite(), start.position().distanceTo(first.centre()));
        }
        Exit last = null;
        while (last == null) {
            int best = -1;
            for (int i = 0; i < cost.length; i++) {
                if (!settled[i] && cost[i] != null && (best < 0 || cost[i].below(cost[best]))) {
                    best = i;
                }
            }
            if (best < 0) {
                return Optional.empty();
            }
            settled[best] = true;
            Exit e = new Exit(junctions.get(best / 4), Compass.values()[best % 4]);
            Waypoint leaving = new Waypoint(e.junction().centre(), e.arm());
            if (goalNext(network, leaving, road, goal)) {
                last = e;
                continue;
            }
            Junction to = junctionNext(network, leaving);
            for (Compass arm : to == null ? List.<Compass>of() : to.arms()) {
                int i = new Exit(to, arm).index();
                Cost c = cost[best].then(arm == e.arm().opposite(), e.junction().centre().distanceTo(to.centre()));
                if (!settled[i] && (cost[i] == null || c.below(cost[i]))) {
                    cost[i] = c;
                    previous[i] = e;
                }
            }
        }
        List<Exit> exits = new ArrayList<>();
        for (Exit e = last; e != null; e = previous[e.index()]) {
            exits.add(0, e);
        }
        List<Waypoint> out = new ArrayList<>();
        // a player takes the waypoints on one road as one, the first of them kept: a route that turns round before it
        // leaves the car's road therefore begins after the turn, where the car is to go once turned
        if (exits.get(0).arm() != start.heading().opposite()) {
            out.add(from);
            out.add(middle(network, from, 0, first.centre(), SQUARE));
        }
        for (Exit e : exits.subList(0, exits.size() - 1)) {
            Waypoint leaving = new Waypoint(e.junction().centre(), e.arm());
            out.add(middle(network, leaving, SQUARE, junctionNext(network, leaving).centre(), SQUARE));
        }
        out.add(middle(network, new Waypoint(last.junction().centre(), last.arm()), SQUARE, goal.point(), 0));
        out.add(goal);
        return Optional.of(new EgoRoute(out));
    }

    /** Driving on from {@code at} the way it heads, along its road: the junction met next, or null at none. */
    private static Junction junctionNext(RoadNetwork network, Waypoint at) {
        Vec2 p = at.point();
        Junction nearest = null;
        for (Road road : network.roads()) {
            if (road.isNorthSouth() != at.heading().isNorthSouth() || !road.contains(p.x(), p.y())) {
                continue;
            }
            for (Junction j : network.junctions()) {
                double ahead = ahead(at, j.centre());
                if (road.carries(j.centre()) && j.hasArm(at.heading().opposite()) && ahead > 1e-9
                        && (nearest == null || ahead < ahead(at, nearest.centre()))) {
                    nearest = j;
                }
            }
        }
        return nearest;
    }

    /** Whether, driving on from {@code at}, the Target ({@code goal}, on {@code targetRoad}) comes before any junction. */
    private static boolean goalNext(RoadNetwork network, Waypoint at, Road targetRoad, Waypoint goal) {
        Vec2 p = at.point();
        double toGoal = ahead(at, goal.point());
        Junction junction = junctionNext(network, at);
        return goal.heading() == at.heading() && targetRoad.contains(p.x(), p.y()) && toGoal > 0
                && (junction == null || toGoal < ahead(at, junction.centre()));
    }

    private static double ahead(Waypoint from, Vec2 to) {
        return (to.x() - from.point().x()) * from.heading().dx() + (to.y() - from.point().y()) * from.heading().dy();
    }

    /**
     * Halfway along the road from {@code from} to {@code to}, leaving out {@code skipFrom} and {@code skipTo} metres
     * of junction square at either end (a point in a square is on no lane of the road but on the junction's), on
     * the centre of the lane it drives in.
     */
    private static Waypoint middle(RoadNetwork network, Waypoint from, double skipFrom, Vec2 to, double skipTo) {
        Vec2 a = from.point();
        Road road = network.roads().stream().filter(r -> r.isNorthSouth() == from.heading().isNorthSouth()
                && r.contains(a.x(), a.y())).findFirst().orElseThrow();
        double ahead = (ahead(from, to) + skipFrom - skipTo) / 2;
        Vec2 p = new Vec2(a.x() + from.heading().dx() * ahead, a.y() + from.heading().dy() * ahead);
        return new Waypoint(road.point(road.along(p.x(), p.y()), road.laneCentre(from.heading())), from.heading());
    }
}
