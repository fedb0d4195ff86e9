package sitcov.judge;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import sitcov.builtin.BuiltinRuns;
import sitcov.control.Vehicle;
import sitcov.oracle.RunResult;
import sitcov.world.MapGenerator;
import sitcov.world.WorldMap;

/**
 * Both seeds fix a run bit for bit, on any thread count. Traces hold the pose of every
 * active vehicle (the autonomous car first) after every tick; records compare doubles bit for bit.
 */
class DeterminismTest {
    private static final long INTERNAL_SEED = 17;

    /** One vehicle after one tick. */
    record Pose(long tick, int id, double x, double y, double heading) {
    }

    /** A run's result and its trace. */
    record Traced(RunResult result, List<Pose> trace) {
    }

    static Traced run(WorldMap map, long internalSeed) {
        List<Pose> trace = new ArrayList<>();
        RunResult result = BuiltinRuns.run(map, internalSeed, Set.of(), (tick, scene, detector) -> {
            for (Vehicle v : java.util.stream.Stream.concat(java.util.stream.Stream.of(scene.car()),
                    scene.movingCars().stream()).toList()) {
                if (v.isActive()) {
                    trace.add(new Pose(tick, v.id(), v.x(), v.y(), v.heading()));
                }
            }
        }).result();
        return new Traced(result, trace);
    }

    @Test
    void theSameSeedsGiveTheSameRunAndTheSameTrace() {
        for (long seed = 1; seed <= 20; seed++) {
            Traced first = run(MapGenerator.generate(seed), INTERNAL_SEED);
            // a map generated afresh from the same seed, so nothing is shared between the runs
            Traced second = run(MapGenerator.generate(seed), INTERNAL_SEED);

            assertEquals(first.result(), second.result(), "map " + seed);
            assertEquals(first.trace(), second.trace(), "map " + seed);
            assertEquals(seed, first.result().externalSeed());
            assertEquals(INTERNAL_SEED, first.result().internalSeed());
            // one pose of the autonomous car per tick simulated
            assertEquals(first.result().ticks(), first.trace().stream().filter(p -> p.id() == 0).count(), "map " + seed);
        }
    }

    @Test
    void anotherInternalSeedChangesTheRunOfSomeMapWithMovingCars() {
        boolean anyDifferent = false;
        for (long seed = 1; seed <= 10 && !anyDifferent; seed++) {
            WorldMap map = MapGenerator.generate(seed);
            assertFalse(map.movingCars().isEmpty(), "map " + seed + " has no moving cars");
            anyDifferent = !run(map, INTERNAL_SEED).trace().equals(run(map, INTERNAL_SEED + 1).trace());
        }
        assertTrue(anyDifferent, "the internal seed changed no trace on maps 1..10");
    }

    @Test
    void runsOnTwoThreadsAreTheSameAsRunsOneAfterAnother() throws Exception {
        List<WorldMap> maps = new ArrayList<>();
        for (long seed = 1; seed <= 10; seed++) {
            maps.add(MapGenerator.generate(seed));
        }
        List<Traced> sequential = new ArrayList<>();
        for (WorldMap map : maps) {
            sequential.add(run(map, INTERNAL_SEED));
        }

        ExecutorService pool = Executors.newFixedThreadPool(2);
        List<Traced> parallel = new ArrayList<>();
        try {
            List<Future<Traced>> futures = new ArrayList<>();
            for (WorldMap map : maps) {
                // the same map objects the sequential runs used: a run must not change its map
                futures.add(pool.submit(() -> run(map, INTERNAL_SEED)));
            }
            for (Future<Traced> f : futures) {
                parallel.add(f.get(60, TimeUnit.SECONDS));
            }
        } finally {
            pool.shutdownNow();
        }

        for (int i = 0; i < maps.size(); i++) {
            assertEquals(sequential.get(i).result(), parallel.get(i).result(), "map " + (i + 1));
            assertEquals(sequential.get(i).trace(), parallel.get(i).trace(), "map " + (i + 1));
        }
    }
}
