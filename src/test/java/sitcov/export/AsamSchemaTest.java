package sitcov.export;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Set;
import org.junit.jupiter.api.Test;
import sitcov.builtin.BuiltinCar;
import sitcov.faults.Fault;
import sitcov.oracle.AccidentType;
import sitcov.oracle.RunResult;
import sitcov.world.MapGenerator;
import sitcov.world.WorldMap;

/**
 * What the export writes is valid against the ASAM schemas: OpenDRIVE 1.7 for the roads, OpenSCENARIO 1.0–1.3
 * for a situation and for a recorded run with accidents (seeds 1..N, {@code -Dsitcov.export.seeds=N}).
 */
class AsamSchemaTest {
    @Test
    void theSchemasRefuseADocumentThatBreaksThemNamingTheLine() {
        String noHeading = OpenDrive.document(MapGenerator.generate(1)).replaceFirst(" hdg=\"[^\"]*\"", "");
        java.util.List<String> errors = AsamSchemas.errors(AsamSchemas.openDrive(), noHeading);
        assertTrue(!errors.isEmpty() && errors.get(0).startsWith("line ") && errors.get(0).contains("hdg"), errors.toString());
        String situation = OpenScenario.situation(MapGenerator.generate(1), "map-1.xodr", ScenarioVersion.V1_0);
        String unknown = situation.replaceFirst("<Storyboard>", "<Storyboard><Unheard/>");
        assertTrue(!AsamSchemas.errors(AsamSchemas.openScenario(ScenarioVersion.V1_0), unknown).isEmpty(),
                "an element OpenSCENARIO does not define is refused");
    }

    @Test
    void theRoadsOfEveryMapAreValidOpenDrive17() {
        ExportSeeds.upTo(20).forEach(seed -> AsamSchemas.assertValid(AsamSchemas.openDrive(),
                OpenDrive.document(MapGenerator.generate(seed)), "the OpenDRIVE of map " + seed));
    }

    @Test
    void theSituationOfEveryMapIsValidInEveryOpenScenarioVersion() {
        ExportSeeds.upTo(20).forEach(seed -> {
            WorldMap map = MapGenerator.generate(seed);
            for (ScenarioVersion v : ScenarioVersion.values()) {
                AsamSchemas.assertValid(AsamSchemas.openScenario(v), OpenScenario.situation(map, "map-" + seed + ".xodr", v),
                        "the OpenSCENARIO " + v + " situation of map " + seed);
            }
        });
    }

    @Test
    void aRecordedRunThatLeavesTheRoadAndTimesOutIsValidOpenScenario() {
        // fault 2 shifts the waypoints: map 5 leaves the road and crosses the centre line, then times out
        WorldMap map = MapGenerator.generate(5);
        RunRecording run = RunRecording.of(map, 5, Set.of(Fault.WAYPOINTS_NORTH_EAST), BuiltinCar.FACTORY);
        RunResult result = run.result();
        assertTrue(result.count(AccidentType.LEAVEROAD) > 0 && result.count(AccidentType.TIMEOUT) > 0,
                "map 5 with fault 2 no longer leaves the road and times out (" + result.countsByType() + "): pick another run");
        // 5000 ticks of six vehicles make 9 MB a document: the oldest and newest versions, the clash run does all four
        for (ScenarioVersion v : new ScenarioVersion[] {ScenarioVersion.V1_0, ScenarioVersion.V1_3}) {
            AsamSchemas.assertValid(AsamSchemas.openScenario(v), OpenScenario.recording(run, "map-5.xodr", v),
                    "the OpenSCENARIO " + v + " recording of map 5 with fault 2");
        }
    }

    @Test
    void aRecordedRunWithClashesIsValidInEveryOpenScenarioVersion() {
        WorldMap map = MapGenerator.generate(33);
        RunRecording run = RunRecording.of(map, 33, Set.of(Fault.TARGET_LANE_CHECK_SKIPPED), BuiltinCar.FACTORY);
        assertTrue(run.result().count(AccidentType.CLASHWITHOBSTACLE) > 0 && run.result().count(AccidentType.CLASHWITHOTHERCAR) > 0,
                "map 33 with fault 14 no longer clashes with a parked and a moving car: pick another run");
        for (ScenarioVersion v : ScenarioVersion.values()) {
            AsamSchemas.assertValid(AsamSchemas.openScenario(v), OpenScenario.recording(run, "map-33.xodr", v),
                    "the OpenSCENARIO " + v + " recording of map 33 with fault 14");
        }
    }
}
