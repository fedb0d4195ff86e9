package sitcov.judge;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import sitcov.builtin.BuiltinCar;
import sitcov.world.MapGenerator;
import sitcov.world.WorldMap;

class SeamRunsTest {
    private static final List<Variant> ALL = VariantList.parse("seam:ALL");

    @Test
    void seamFaultsAreJudgedAlikeForkedFromTheReferenceAndRunWhole() {
        int found = 0;
        int forkedLate = 0;
        int neverDeparted = 0;
        for (long seed = 1; seed <= 4; seed++) {
            WorldMap map = MapGenerator.generate(seed);
            FaultyRuns length = seed <= 2 ? FaultyRuns.TO_END : FaultyRuns.UNTIL_VERDICT;
            JudgedMap whole = MapRunner.judgeVariants(map, seed, ALL, length, BuiltinCar.FACTORY.unforked(), c -> null);
            JudgedMap forked = MapRunner.judgeVariants(map, seed, ALL, length, BuiltinCar.FACTORY, c -> null);
            assertEquals(whole, forked, "map " + seed + " " + length);
            for (FaultVerdict v : whole.verdicts()) {
                found += v.detection().found() ? 1 : 0;
                forkedLate += v.firstEffectiveTick() > 10 ? 1 : 0;
                neverDeparted += v.effective() ? 0 : 1;
            }
        }
        assertTrue(found > 0, "some seam faults are found, so forked runs with accidents were compared");
        assertTrue(forkedLate > 0, "some depart well after the start, so forks from a checkpoint were compared");
        assertTrue(neverDeparted > 0, "some never act, so verdicts from the shadows were compared");
    }

    @Test
    void theReferenceRunIsTheSameWhetherOrNotItWatchesSeamFaults() {
        WorldMap map = MapGenerator.generate(3);
        JudgedMap watched = MapRunner.judgeVariants(map, 3, ALL, FaultyRuns.UNTIL_VERDICT, BuiltinCar.FACTORY, c -> null);
        assertEquals(Simulator.run(map, 3, java.util.Set.of(), RunObserver.NONE, BuiltinCar.FACTORY).result(),
                watched.faultFree());
    }
}
