package sitcov.judge;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Set;
import org.junit.jupiter.api.Test;
import sitcov.faults.Fault;
import sitcov.world.MapGenerator;
import sitcov.world.WorldMap;

class LiveRunTest {
    private static RunRecord toEnd(LiveRun run) {
        while (run.step()) {
            // stepped to the end
        }
        return run.record();
    }

    @Test
    void aCopyTakenMidRunEndsAsTheRunItselfAndAsAFreshRunDo() {
        int withAccidents = 0;
        for (long seed = 1; seed <= 6; seed++) {
            WorldMap map = MapGenerator.generate(seed);
            Set<Fault> faults = seed % 2 == 0 ? Set.of() : Set.of(Fault.ofId((int) seed % 20));
            RunRecord fresh = toEnd(new LiveRun(map, seed * 7, faults));
            LiveRun run = new LiveRun(map, seed * 7, faults);
            for (long t = 0; t < fresh.result().ticks() / 2; t++) {
                run.step();
            }
            LiveRun copy = run.copy();
            assertNotSame(run.scene(), copy.scene());
            RunRecord fromCopy = toEnd(copy);
            RunRecord fromOriginal = toEnd(run);
            String seeds = "map " + seed + " internal seed " + seed * 7 + " faults " + faults;
            assertEquals(fresh, fromCopy, seeds);
            assertEquals(fresh, fromOriginal, seeds);
            withAccidents += fresh.result().hasAccident() ? 1 : 0;
        }
        assertTrue(withAccidents > 0, "some of the runs copied have accidents");
    }
}
