package sitcov.export;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Optional;
import java.util.Set;
import org.junit.jupiter.api.Test;
import sitcov.builtin.BuiltinCar;
import sitcov.faults.Fault;
import sitcov.oracle.AccidentType;
import sitcov.oracle.Outcome;
import sitcov.world.MapGenerator;

/**
 * A found run whose car stopped for good is exported to 5 s after it stopped, not to its timeout 1000 s on
 * (src/main/java/sitcov/export/README.md, "How big an export is"), and says where the accident that found it lies.
 */
class StandingCutTest {
    /** A map of {@code run smoke} on which fault 17 stops the car for good long before its timeout. */
    private static final RunRecording STANDS = RunRecording.of(MapGenerator.generate(570240261368197319L),
            7262292177969351214L, Set.of(Fault.STOPS_TURNING_WHILE_OVERTAKING), BuiltinCar.FACTORY);

    @Test
    void aRunThatTimesOutStandingIsCutFiveSecondsAfterItsCarLastMoved() {
        assertEquals(Outcome.TIMEOUT, STANDS.result().outcome(), "the case this test needs: a run that times out");
        RunRecording cut = STANDS.cutAfterStandingFor(25);
        assertTrue(cut.lastTick() < 1000, "cut long before the timeout: " + cut.lastTick());
        List<RunRecording.Sample> ego = STANDS.tracks().get(0).samples();
        RunRecording.Sample end = ego.get(ego.size() - 1);
        // sample k is the state after tick k - 1; the car stood from 25 ticks before the cut to the run's end
        int stoodFrom = (int) cut.lastTick() - 25 + 1;
        for (int k = stoodFrom; k < ego.size(); k++) {
            assertEquals(end, ego.get(k), "sample " + k + " after the car stopped for good");
        }
        assertNotEquals(end, ego.get(stoodFrom - 1), "the car moved in the tick before it stood");
        assertEquals(cut.lastTick() + 2, cut.tracks().get(0).samples().size());
        assertEquals(STANDS.lastTick(), STANDS.cutAfterStandingFor(1_000_000).lastTick(), "a later cut keeps the run whole");
    }

    @Test
    void theCutRunSaysThatTheTimeoutThatFoundItLiesAfterItsEnd() {
        RunRecording cut = STANDS.cutAfterStandingFor(25);
        var timeout = STANDS.result().accidents().stream().filter(a -> a.type() == AccidentType.TIMEOUT).findFirst()
                .orElseThrow();
        String document = OpenScenario.recording(cut, Optional.of(timeout), "map.xodr", ScenarioVersion.V1_0);
        ScenarioModel m = ScenarioModel.parse(document);
        String foundBy = m.properties().get("ego").get("sitcovFoundBy");
        assertTrue(foundBy.startsWith("TIMEOUT at tick " + timeout.tick() + " ") && foundBy.contains("after the recording's"
                + " end at tick " + cut.lastTick()), foundBy);
        String whole = OpenScenario.recording(STANDS, Optional.of(timeout), "map.xodr", ScenarioVersion.V1_0);
        assertTrue(document.length() * 10 < whole.length(), document.length() + " bytes against " + whole.length());
    }
}
