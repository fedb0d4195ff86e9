package sitcov.judge;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.EnumSet;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;
import sitcov.builtin.BuiltinRuns;
import sitcov.faults.Activation;
import sitcov.faults.Fault;
import sitcov.vehicles.AutonomousCar;
import sitcov.world.MapGenerator;
import sitcov.world.WorldMap;

/**
 * A seeded fault is the only difference between a faulty run and the fault-free run of the same
 * seeds: until the tick it first changes a value the car uses, the two runs are the same tick for
 * tick, and a fault that never does so leaves the whole run unchanged.
 */
class FaultIsolationTest {
    private static final long[] MAPS = {3, 7, 13};

    private static List<String> trajectory(WorldMap map, long internalSeed, Set<Fault> faults, List<Activation> out) {
        List<String> states = new ArrayList<>();
        RunRecord record = BuiltinRuns.run(map, internalSeed, faults, (tick, scene, detector) -> {
            var car = scene.car();
            states.add(tick + ":" + car.x() + "," + car.y() + "," + car.heading() + "," + car.speed()
                    + "," + detector.accidents().size());
        });
        out.addAll(record.activations());
        return states;
    }

    @Test
    void aFaultChangesNothingBeforeItsFirstEffectiveTick() {
        for (long seed : MAPS) {
            WorldMap map = MapGenerator.generate(seed);
            List<String> faultFree = trajectory(map, seed, Set.of(), new ArrayList<>());
            for (Fault fault : Fault.values()) {
                List<Activation> activations = new ArrayList<>();
                List<String> faulty = trajectory(map, seed, EnumSet.of(fault), activations);
                Activation a = activations.get(fault.ordinal());
                String replay = "map " + seed + ", internal seed " + seed + ", fault " + fault.id();
                if (!a.effective()) {
                    assertEquals(faultFree, faulty, replay + ": never effective, yet the run changed");
                    continue;
                }
                // the state after tick t reflects decisions made in tick t, so ticks before the first effective one agree
                int same = (int) Math.min(a.firstEffectiveTick(), Math.min(faultFree.size(), faulty.size()));
                assertEquals(faultFree.subList(0, same), faulty.subList(0, same),
                        replay + ": the run changed before the fault's first effective tick " + a.firstEffectiveTick());
            }
        }
    }

    @Test
    void anInactiveFaultRecordsNoActivation() {
        List<Activation> activations = new ArrayList<>();
        trajectory(MapGenerator.generate(MAPS[0]), MAPS[0], Set.of(), activations);
        assertTrue(activations.stream().noneMatch(a -> a.active() || a.reached() || a.effective()),
                "fault-free run of map " + MAPS[0] + " recorded an activation: " + activations);
    }
}
