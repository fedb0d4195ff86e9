package sitcov.judge;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import sitcov.builtin.BuiltinCar;
import sitcov.faults.Fault;
import sitcov.world.MapGenerator;
import sitcov.world.SituationFile;
import sitcov.world.WorldMap;

class ForkedRunsTest {
    private static final List<Fault> ALL = List.of(Fault.values());

    @Test
    void everyRegressionSituationIsJudgedAlikeForkedAndWhole() throws Exception {
        // each situation's own fault, to its verdict (all twenty faults, both ways, were checked by hand: 78 s)
        for (FaultDetectionRegressionTest.Case c : FaultDetectionRegressionTest.cases()) {
            WorldMap map = SituationFile.read(FaultDetectionRegressionTest.FOLDER.resolve(c.file()));
            List<Fault> own = List.of(c.fault());
            JudgedMap whole = MapRunner.judge(map, c.internalSeed(), own, FaultyRuns.UNTIL_VERDICT,
                    BuiltinCar.FACTORY.unforked());
            JudgedMap forked = MapRunner.judge(map, c.internalSeed(), own, FaultyRuns.UNTIL_VERDICT, BuiltinCar.FACTORY);
            assertEquals(whole, forked, c.replay());
        }
    }

    @Test
    void generatedMapsAreJudgedAlikeForkedAndWholeAndSomeFaultsNeedNoRunOfTheirOwn() {
        int found = 0;
        int neverDeparted = 0;
        for (long seed = 1; seed <= 6; seed++) {
            WorldMap map = MapGenerator.generate(seed);
            FaultyRuns length = seed <= 2 ? FaultyRuns.TO_END : FaultyRuns.UNTIL_VERDICT;
            JudgedMap whole = MapRunner.judge(map, seed, ALL, length, BuiltinCar.FACTORY.unforked());
            JudgedMap forked = MapRunner.judge(map, seed, ALL, length, BuiltinCar.FACTORY);
            assertEquals(whole, forked, "map " + seed + " internal seed " + seed + " " + length);
            for (FaultVerdict v : whole.verdicts()) {
                found += v.detection().found() ? 1 : 0;
                neverDeparted += v.effective() ? 0 : 1;
            }
        }
        assertTrue(found > 0, "some faults are found, so forked runs with accidents were compared");
        assertTrue(neverDeparted > 0, "some faults never act, so verdicts from the shadows were compared");
    }
}
