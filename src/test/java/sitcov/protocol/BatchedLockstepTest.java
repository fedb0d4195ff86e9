package sitcov.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;
import sitcov.faults.Fault;
import sitcov.judge.BatchedRuns;
import sitcov.judge.LiveRun;
import sitcov.judge.RunObserver;
import sitcov.judge.RunRecord;
import sitcov.judge.Simulator;
import sitcov.world.MapGenerator;
import sitcov.builtin.BuiltinCar;
import sitcov.world.WorldMap;

/** Batched lockstep: runs stepped B at a time over one controller are the runs stepped one at a time. */
class BatchedLockstepTest {
    private static final int RUNS = 6;

    private static Set<Fault> faults(int i) {
        return i % 3 == 0 ? Set.of(Fault.ofId(16)) : Set.of();
    }

    private static RunRecord run(int i, sitcov.control.ControllerFactory controller) {
        long seed = i + 1;
        WorldMap map = MapGenerator.generate(seed);
        return Simulator.run(map, seed, faults(i), RunObserver.NONE, controller);
    }

    private static LiveRun live(int i, sitcov.control.ControllerFactory controller) {
        long seed = i + 1;
        return new LiveRun(MapGenerator.generate(seed), seed, faults(i), controller);
    }

    private static List<RunRecord> oneAtATime() {
        List<RunRecord> records = new ArrayList<>();
        try (ProxyFactory one = Pipes.serving(BuiltinCar.FACTORY, Set.of())) {
            for (int i = 0; i < RUNS; i++) {
                records.add(run(i, one));
            }
        }
        return records;
    }

    @Test
    void runsBatchedByFourAreTheRunsOneAtATime() throws ControllerStartException {
        List<RunRecord> single = oneAtATime();
        try (BatchingProxy four = Pipes.batching(BuiltinCar.FACTORY, 4, 4)) {
            assertEquals(4, four.batch());
            List<RunRecord> batched = BatchedRuns.run(RUNS, four, BatchedLockstepTest::live);
            for (int i = 0; i < RUNS; i++) {
                assertEquals(single.get(i), batched.get(i), "run " + i + ": " + batched.get(i).result().failureReason());
            }
        }
        assertTrue(single.stream().anyMatch(r -> r.result().ticks() > 100), "the runs are not trivially short");
    }

    @Test
    void theSmallerBatchIsTaken() throws ControllerStartException {
        try (BatchingProxy proxy = Pipes.batching(BuiltinCar.FACTORY, 2, 8)) {
            assertEquals(2, proxy.batch());
            assertEquals(oneAtATime(), BatchedRuns.run(RUNS, proxy, BatchedLockstepTest::live));
        }
        // a controller that takes one run at a time is sent today's messages
        try (BatchingProxy proxy = Pipes.batching(BuiltinCar.FACTORY, 1, 8)) {
            assertEquals(1, proxy.batch());
            assertEquals(oneAtATime().subList(0, 2), BatchedRuns.run(2, proxy, BatchedLockstepTest::live));
        }
    }
}
