package sitcov.judge;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import sitcov.builtin.BuiltinRuns;
import sitcov.oracle.Accident;
import sitcov.oracle.Outcome;
import sitcov.oracle.RunResult;
import sitcov.world.SituationFile;
import sitcov.world.WorldMap;

class MapRunnerTest {
    @Test
    void faultyRunsStoppedAtTheirVerdictGiveTheVerdictsOfRunsDrivenToTheEnd() throws Exception {
        int stoppedEarly = 0;
        long ticksSaved = 0;
        for (FaultDetectionRegressionTest.Case c : FaultDetectionRegressionTest.cases()) {
            WorldMap map = SituationFile.read(FaultDetectionRegressionTest.FOLDER.resolve(c.file()));
            List<sitcov.faults.Fault> faults = List.of(c.fault());
            FaultVerdict toEnd = BuiltinRuns.judge(map, c.internalSeed(), faults, FaultyRuns.TO_END).verdicts().get(0);
            FaultVerdict untilVerdict = BuiltinRuns.judge(map, c.internalSeed(), faults, FaultyRuns.UNTIL_VERDICT)
                    .verdicts().get(0);
            String seeds = c.replay();
            assertEquals(toEnd.detection(), untilVerdict.detection(), seeds);
            assertEquals(toEnd.newAccident(), untilVerdict.newAccident(), seeds);
            assertEquals(toEnd.foundByPaperNotion(), untilVerdict.foundByPaperNotion(), seeds);
            RunResult whole = toEnd.faultyRun();
            RunResult cut = untilVerdict.faultyRun();
            if (cut.outcome() != Outcome.STOPPED_AT_VERDICT) {
                assertEquals(whole, cut, "a run not stopped is the whole run; " + seeds);
                continue;
            }
            // stopped at the end of the tick of the first accident the fault-free run lacks, having
            // seen exactly the accidents of the whole run up to that tick
            Accident first = toEnd.newAccident().orElseThrow();
            assertEquals(first.tick() + 1, cut.ticks(), seeds);
            assertEquals(whole.accidents().stream().filter(a -> a.tick() <= first.tick()).toList(), cut.accidents(), seeds);
            assertTrue(cut.ticks() < whole.ticks(), seeds);
            stoppedEarly++;
            ticksSaved += whole.ticks() - cut.ticks();
        }
        // the regression situations show faults found before the end: 14 of the 20 stop early (29 927 ticks saved)
        assertTrue(stoppedEarly >= 10, "stopped early: " + stoppedEarly + ", ticks saved " + ticksSaved);
    }
}
