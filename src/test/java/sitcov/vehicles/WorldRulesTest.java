package sitcov.vehicles;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.function.BiConsumer;
import org.junit.jupiter.api.Test;
import sitcov.control.Command;
import sitcov.control.ControllerFactory;
import sitcov.control.Observation;
import sitcov.judge.LiveRun;
import sitcov.oracle.Outcome;
import sitcov.world.MapGenerator;
import sitcov.world.Situations;
import sitcov.world.WorldMap;

/**
 * The world's rules as experiments/controllers/README.md, "How the car moves" states them: its worked example of one
 * command and the next pose, driven through the controller seam; the junction-claim rules, whose
 * breach ends the run in CONTROLLER_ERROR naming the rule; and the count of clamped ticks.
 */
class WorldRulesTest {
    private static final WorldMap STRAIGHT = Situations.withoutTraffic(Situations.straight(List.of()));

    @Test
    void theReadmesWorkedExampleGivesTheDocumentedPose() {
        // the straight test road: the car starts at (40, 48.5) heading 90 (east), standing
        List<double[]> poses = new ArrayList<>();
        LiveRun run = run(STRAIGHT, (now, out) -> {
            poses.add(new double[] {now.x(), now.y(), now.heading(), now.speed()});
            if (now.tick() == 0) {
                out.speedChange(1.5).steering(10);
            } else {
                out.speed(0);
            }
        }, 2);
        assertArrayNear(new double[] {40, 48.5, 90, 0}, poses.get(0), 1e-12);
        // the worked example: heading 100; the rear axle, 1.5 m behind the front, stays at (38.5, 48.5); the front
        // swings to (39.9772, 48.2395) and then moves 1.5 m along bearing 100 to (41.4544, 47.9791)
        assertArrayNear(new double[] {41.4544, 47.9791, 100, 1.5}, poses.get(1), 5e-5);
        double h = Math.toRadians(100);
        assertArrayNear(new double[] {38.5 + 3 * Math.sin(h), 48.5 + 3 * Math.cos(h), 100, 1.5}, poses.get(1), 1e-9);
        assertEquals(0, run.scene().autonomousCar().clampedTicks());
    }

    @Test
    void aStandingCarTurnsAboutItsRearAxle() {
        List<double[]> poses = new ArrayList<>();
        run(STRAIGHT, (now, out) -> {
            poses.add(new double[] {now.x(), now.y(), now.heading(), now.speed()});
            out.steering(-15);
        }, 2);
        double h = Math.toRadians(75);
        assertArrayNear(new double[] {38.5 + 1.5 * Math.sin(h), 48.5 + 1.5 * Math.cos(h), 75, 0}, poses.get(1), 1e-9);
    }

    @Test
    void theWorldClampsToTheLimitsAndCountsTheTicks() {
        List<double[]> poses = new ArrayList<>();
        LiveRun run = run(STRAIGHT, (now, out) -> {
            poses.add(new double[] {now.speed(), now.heading()});
            if (now.tick() < 2) {
                out.speedChange(4).steering(now.tick() == 0 ? 20 : 0);
            }
        }, 4);
        assertArrayNear(new double[] {2.5, 105}, poses.get(1), 1e-12);
        assertEquals(2, run.scene().autonomousCar().clampedTicks());
        assertEquals(2, run.record().result().clampedTicks());
    }

    @Test
    void aClaimOfAJunctionTheMapDoesNotHaveIsAControllerError() {
        LiveRun run = run(STRAIGHT, (now, out) -> out.claim(99), 3);
        assertBroke(run, "it claimed junction 99, which the map does not have");
    }

    @Test
    void aClaimFarFromTheJunctionsSquareIsAControllerError() {
        WorldMap map = MapGenerator.generate(1);
        int far = farthestJunction(map);
        LiveRun run = run(map, (now, out) -> out.claim(far), 3);
        assertBroke(run, "a junction may be claimed only within 30 m of its square");
    }

    @Test
    void threeJunctionsMayBeHeldAtOnceNotFour() {
        // the first generated map whose car starts within 30 m of four junction squares
        WorldMap map = null;
        List<Integer> near = List.of();
        for (long seed = 1; near.size() < 4; seed++) {
            map = MapGenerator.generate(seed);
            near = junctionsNearTheStart(map);
        }
        List<Integer> three = near.subList(0, 3);
        LiveRun allowed = run(map, (now, out) -> three.forEach(out::claim), 1);
        assertEquals(null, allowed.scene().autonomousCar().failure());
        List<Integer> four = near.subList(0, 4);
        LiveRun broke = run(map, (now, out) -> four.forEach(out::claim), 1);
        assertBroke(broke, "a car may hold at most 3 at once");
    }

    private static List<Integer> junctionsNearTheStart(WorldMap map) {
        var start = map.layout().carStart().orElseThrow().position();
        List<Integer> near = new ArrayList<>();
        for (var j : map.layout().junctions()) {
            var square = j.square();
            double dx = Math.max(0, Math.max(square.minX() - start.x(), start.x() - square.maxX()));
            double dy = Math.max(0, Math.max(square.minY() - start.y(), start.y() - square.maxY()));
            if (Math.hypot(dx, dy) <= JunctionRules.CLAIM_WITHIN) {
                near.add(j.id());
            }
        }
        return near;
    }

    private static int farthestJunction(WorldMap map) {
        var start = map.layout().carStart().orElseThrow().position();
        int far = -1;
        double most = -1;
        for (var j : map.layout().junctions()) {
            double d = j.centre().distanceTo(start.x(), start.y());
            if (d > most) {
                most = d;
                far = j.id();
            }
        }
        assertTrue(most > 40, "map 1 should have a junction far from the start");
        return far;
    }

    private static void assertBroke(LiveRun run, String rule) {
        assertEquals(Outcome.CONTROLLER_ERROR, run.record().result().outcome());
        String message = run.scene().autonomousCar().failure().getMessage();
        assertTrue(message.startsWith("the controller broke the world's rules: "), message);
        assertTrue(message.contains(rule), message);
    }

    /** Runs {@code ticks} ticks (or to the end) with a controller that fills each command by {@code drive}. */
    private static LiveRun run(WorldMap map, BiConsumer<Observation, Command> drive, int ticks) {
        ControllerFactory factory = start -> drive::accept;
        LiveRun run = new LiveRun(map, 1, Set.of(), factory);
        for (int i = 0; i < ticks && run.step(); i++) {
            // step by step
        }
        return run;
    }

    private static void assertArrayNear(double[] expected, double[] actual, double tolerance) {
        for (int i = 0; i < expected.length; i++) {
            assertEquals(expected[i], actual[i], tolerance, "component " + i);
        }
    }
}
