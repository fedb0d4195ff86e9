package sitcov.export;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import sitcov.geom.Compass;
import sitcov.geom.Vec2;
import sitcov.world.Dimensions;
import sitcov.world.Junction;
import sitcov.world.MapGenerator;
import sitcov.world.Road;
import sitcov.world.StartPose;
import sitcov.world.Target;
import sitcov.world.WorldMap;

/**
 * A situation gives the car under test its route to the Target as waypoints a player can follow: each on a lane
 * centre, heading the way the lane carries traffic and outside every junction's square; in driving order, each
 * next one ahead in the same lane or past a junction ahead, turning round there where the route must; from the
 * car's start (or, where the route turns round before leaving the car's road, from just after the turn) to the
 * Target's place on its lane (src/main/java/sitcov/export/README.md, "The situation").
 */
class EgoRouteTest {
    private record Point(Vec2 at, Compass heading) {
    }

    @Test
    void everySituationsRouteRunsAlongLaneCentresInDrivingOrderFromTheStartToTheTarget() {
        Failures failures = new Failures();
        int turning = 0;
        int straight = 0;
        for (long seed : ExportSeeds.upTo(100).toArray()) {
            WorldMap map = MapGenerator.generate(seed);
            if (!map.layout().isRunnable()) {
                continue;
            }
            ScenarioModel m = ScenarioModel.parse(OpenScenario.situation(map, "map.xodr", ScenarioVersion.V1_0));
            List<Point> route = m.routeWaypoints().stream().map(p -> new Point(new Vec2(p.x(), Dimensions.WORLD_HEIGHT - p.y()),
                    compass(p.h()))).toList();
            List<String> problems = problems(map, route);
            problems.forEach(p -> failures.add(seed, p + " in the route " + route));
            boolean turns = false;
            for (int i = 1; i < route.size(); i++) {
                turns |= route.get(i).heading() == route.get(i - 1).heading().opposite();
            }
            turning += turns ? 1 : 0;
            straight += route.size() == 2 ? 1 : 0;
        }
        failures.assertNone("a situation's route runs along the lanes from the start to the Target");
        assertTrue(turning > 10 && straight > 0, "among maps 1..100, routes that turn round: " + turning
                + "; routes of the start and the Target alone: " + straight + "; the checks need both");
    }

    private static List<String> problems(WorldMap map, List<Point> route) {
        List<String> problems = new ArrayList<>();
        if (route.size() < 2) {
            return List.of("fewer than two waypoints");
        }
        for (Point p : route) {
            if (lane(map, p) == null) {
                problems.add(p + " is on no lane centre heading its way");
            }
            if (map.layout().junctions().stream().anyMatch(j -> j.contains(p.at().x(), p.at().y()))) {
                problems.add(p + " is inside a junction's square");
            }
        }
        if (!problems.isEmpty()) {
            return problems;
        }
        for (int i = 1; i < route.size(); i++) {
            if (!follows(map, route.get(i - 1), route.get(i))) {
                problems.add(route.get(i) + " is not ahead of " + route.get(i - 1) + ", nor past a junction ahead of it");
            }
        }
        StartPose start = map.layout().carStart().orElseThrow();
        Point first = route.get(0);
        boolean fromStart = first.at().distanceTo(start.position()) < 1e-3 && first.heading() == start.heading();
        boolean afterTurn = first.heading() == start.heading().opposite()
                && lane(map, first).contains(start.position().x(), start.position().y());
        if (!fromStart && !afterTurn) {
            problems.add("it starts at " + first + ", neither the start " + start + " nor its road the other way");
        }
        Target target = map.layout().target().orElseThrow();
        Road road = map.layout().roads().get(target.roadId());
        Point last = route.get(route.size() - 1);
        Compass lane = road.laneDirectionAt(target.position().x(), target.position().y());
        if (last.heading() != lane || lane(map, last) != road || Math.abs(road.along(last.at().x(), last.at().y())
                - road.along(target.position().x(), target.position().y())) > 1e-3) {
            problems.add("it ends at " + last + ", not level with the Target " + target.position() + " in its lane " + lane);
        }
        return problems;
    }

    /** The road whose lane centre {@code p} is on, heading the lane's way, or null. */
    private static Road lane(WorldMap map, Point p) {
        for (Road r : map.layout().roads()) {
            if (r.isNorthSouth() == p.heading().isNorthSouth() && r.contains(p.at().x(), p.at().y())
                    && Math.abs(r.across(p.at().x(), p.at().y()) - r.laneCentre(p.heading())) < 1e-3) {
                return r;
            }
        }
        return null;
    }

    /** Whether {@code b} is where a car at {@code a} comes next: ahead in its lane, or past a junction ahead of it. */
    private static boolean follows(WorldMap map, Point a, Point b) {
        if (a.heading() == b.heading() && lane(map, a) == lane(map, b) && ahead(a, b.at()) > 0) {
            return true;
        }
        for (Junction j : map.layout().junctions()) {
            boolean reached = lane(map, a).carries(j.centre()) && ahead(a, j.centre()) > 0;
            boolean left = j.hasArm(b.heading()) && lane(map, b).carries(j.centre()) && ahead(b, j.centre()) < 0;
            if (reached && left) {
                return true;
            }
        }
        return false;
    }

    private static double ahead(Point from, Vec2 to) {
        return (to.x() - from.at().x()) * from.heading().dx() + (to.y() - from.at().y()) * from.heading().dy();
    }

    /** The compass direction of an ASAM heading (radians anticlockwise from east, y northwards). */
    private static Compass compass(double h) {
        double bearing = Math.toDegrees(h) + 90;
        for (Compass c : Compass.values()) {
            if (Math.abs(Math.IEEEremainder(c.bearing() - bearing, 360)) < 1e-3) {
                return c;
            }
        }
        throw new AssertionError("heading " + h + " is no compass direction");
    }
}
