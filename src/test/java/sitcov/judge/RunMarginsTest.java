package sitcov.judge;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import sitcov.builtin.BuiltinRuns;
import sitcov.experiment.MapId;
import sitcov.experiment.SeedPlan;
import sitcov.oracle.AccidentType;
import sitcov.oracle.Outcome;
import sitcov.oracle.RunResult;
import sitcov.world.MapGenerator;
import sitcov.world.WorldMap;

class RunMarginsTest {
    /** Maps on which the fault-free car failed with master seed 2026's internal seeds (off road, centre line, timeout), and ordinary ones. */
    private static final List<Long> SEEDS = List.of(5963020L, 1781788L, 2439065L, 1L, 2L, 3L, 4L, 5L, 6L, 7L);

    @Test
    void everyRunsRobustnessIsNegativeExactlyForTheAccidentTypesItHad() {
        int failing = 0;
        for (long seed : SEEDS) {
            WorldMap map = MapGenerator.generate(seed);
            RunResult r = BuiltinRuns.run(map, SeedPlan.internalSeed(2026, new MapId.Seeded(map.seed())));
            failing += r.hasAccident() ? 1 : 0;
            for (AccidentType t : List.of(AccidentType.CLASHWITHOBSTACLE, AccidentType.CLASHWITHOTHERCAR,
                    AccidentType.LEAVEROAD, AccidentType.CROSSCENTRELINE)) {
                assertEquals(r.count(t) > 0, r.margins().robustness(t) < 0, "map " + seed + ", " + t);
            }
            // ρ(◇ atTarget) = 5000 − the tick the Target was reached (ticks counts from tick 0), 0 on a timeout
            double timeout = r.outcome() == Outcome.TIMEOUT ? 0 : 5000 - (r.ticks() - 1);
            assertEquals(timeout, r.margins().robustness(AccidentType.TIMEOUT), "map " + seed);
        }
        assertTrue(failing >= 3, "the maps chosen to fail failed: " + failing);
    }
}
