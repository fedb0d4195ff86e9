package sitcov.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import java.util.Set;
import org.junit.jupiter.api.Test;
import sitcov.builtin.BuiltinCar;
import sitcov.builtin.BuiltinRuns;
import sitcov.faults.Activation;
import sitcov.faults.Fault;
import sitcov.judge.RunObserver;
import sitcov.judge.RunRecord;
import sitcov.judge.Simulator;
import sitcov.world.MapGenerator;
import sitcov.world.WorldMap;

/**
 * The protocol carries everything a controller needs: the builtin car served over it (through
 * pipes, on a thread) drives every run exactly as it does in process, faults and all.
 */
class BuiltinOverTheProtocolTest {
    private static final List<Long> SEEDS = List.of(1L, 2L, 3L, 4L, 5L, 6L);

    /** A map on which each fault is effective (checked below): fault 17's runs are long, it gets one. */
    private static final Map<Integer, List<Long>> FAULTY_SEEDS = Map.of(8, List.of(6L), 16, List.of(1L),
            17, List.of(1L), 18, List.of(6L, 7L), 19, List.of(7L));

    @Test
    void aFaultFreeRunOverThePipeIsTheInProcessRun() {
        assertSameRuns(SEEDS, Set.of());
    }

    @Test
    void faultsSwitchedOnInTheRunActOverThePipeAndTheirActivationsComeBack() {
        for (int id : List.of(8, 16, 17, 18, 19)) {
            int effective = assertSameRuns(FAULTY_SEEDS.get(id), Set.of(Fault.ofId(id)));
            assertTrue(effective > 0, "fault " + id + " was effective on none of the maps: its activations prove nothing");
        }
    }

    @Test
    void a64BitInternalSeedCrossesThePipeExactly() {
        // the served car draws its exit choices from the internal seed's streams: a rounded seed would choose otherwise
        long seed = -8_070_450_532_247_928_833L;
        try (ProxyFactory pipe = Pipes.serving(BuiltinCar.FACTORY, Set.of())) {
            for (long map = 1; map <= 3; map++) {
                WorldMap world = MapGenerator.generate(map);
                assertEquals(BuiltinRuns.run(world, seed, Set.of(), RunObserver.NONE),
                        Simulator.run(world, seed, Set.of(), RunObserver.NONE, pipe), "map " + map);
            }
        }
    }

    @Test
    void faultsTheServerSwitchesOnAreReportedAsReachedInTheRun() {
        // the run switches no fault on; the served car has fault 8 (its camera) and reports what it did
        try (ProxyFactory served = Pipes.serving(BuiltinCar.FACTORY, Set.of(Fault.ofId(8)))) {
            WorldMap map = MapGenerator.generate(1);
            RunRecord viaPipe = Simulator.run(map, 1, Set.of(), RunObserver.NONE, served);
            RunRecord inProcess = BuiltinRuns.run(map, 1, Set.of(Fault.ofId(8)), RunObserver.NONE);
            assertEquals(inProcess.result(), viaPipe.result());
            Activation camera = viaPipe.activations().get(8);
            assertTrue(camera.reached() && !camera.active(), "the served car's fault is reached, not switched on by the run");
            assertEquals(inProcess.activations().get(8).effectiveCount(), camera.effectiveCount());
        }
    }

    /** Runs every seed both ways, one served car for them all; returns how many runs had a fault effective. */
    private static int assertSameRuns(List<Long> seeds, Set<Fault> faults) {
        int effective = 0;
        try (ProxyFactory pipe = Pipes.serving(BuiltinCar.FACTORY, Set.of())) {
            for (long seed : seeds) {
                WorldMap map = MapGenerator.generate(seed);
                RunRecord inProcess = BuiltinRuns.run(map, seed, faults, RunObserver.NONE);
                RunRecord viaPipe = Simulator.run(map, seed, faults, RunObserver.NONE, pipe);
                assertEquals(inProcess, viaPipe, "seed " + seed + " with faults " + faults);
                if (inProcess.activations().stream().anyMatch(Activation::effective)) {
                    effective++;
                }
            }
        }
        return effective;
    }
}
