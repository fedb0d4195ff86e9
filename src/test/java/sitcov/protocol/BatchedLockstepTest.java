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

    @Test
    void aControllerThatBreaksFailsEveryWaitingRunWithItsReasonAndTheNextRunsStartAfresh()
            throws ControllerStartException {
        java.util.concurrent.atomic.AtomicBoolean broke = new java.util.concurrent.atomic.AtomicBoolean();
        Pipes.Peer server = (in, out) -> new ControllerServer(BuiltinCar.FACTORY, "in-process", "test", Set.of(),
                Wire.PROTOCOL, 4).serve(in, new java.io.FilterOutputStream(out) {
                    private final java.io.ByteArrayOutputStream line = new java.io.ByteArrayOutputStream();

                    @Override
                    public void write(int b) throws java.io.IOException {
                        line.write(b);
                        if (b == '\n') {
                            String text = line.toString(java.nio.charset.StandardCharsets.UTF_8);
                            line.reset();
                            // the first answer to tick 20's observations is garbage, once
                            if (text.startsWith("{\"type\":\"commands\"") && text.contains("\"tick\":20,")
                                    && broke.compareAndSet(false, true)) {
                                text = "garbage\n";
                            }
                            out.write(text.getBytes(java.nio.charset.StandardCharsets.UTF_8));
                            out.flush();
                        }
                    }

                    @Override
                    public void write(byte[] b, int off, int len) throws java.io.IOException {
                        for (int i = 0; i < len; i++) {
                            write(b[off + i]);
                        }
                    }
                });
        List<RunRecord> single = oneAtATime();
        List<RunRecord> batched;
        try (BatchingProxy four = Pipes.batching(server, 4)) {
            batched = BatchedRuns.run(RUNS, four, BatchedLockstepTest::live);
        }
        assertTrue(broke.get(), "the controller broke");
        // the four runs in progress at tick 20: two waited for the broken answer, two for the next one
        for (int i = 0; i < 4; i++) {
            String why = batched.get(i).result().failureReason();
            assertTrue(why.contains("at tick 20 it wrote 'garbage'"), "run " + i + ": " + why);
        }
        for (int i = 4; i < RUNS; i++) {
            assertEquals(single.get(i), batched.get(i), "run " + i + " started with a fresh controller");
        }
    }
}
