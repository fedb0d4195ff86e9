package sitcov.export;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Optional;
import java.util.Set;
import org.junit.jupiter.api.Test;
import sitcov.builtin.BuiltinCar;
import sitcov.faults.Fault;
import sitcov.world.MapGenerator;
import sitcov.world.WorldMap;

/**
 * Each OpenSCENARIO version is written without what its own schema marks deprecated (from 1.2: parameters set as
 * the scenario runs, ReachPositionCondition, the parameter type "integer"), in a situation and in recordings with
 * every kind of declared event (src/main/java/sitcov/export/README.md, "Validated in the build").
 */
class DeprecatedConstructsTest {
    @Test
    void noVersionUsesWhatItsOwnSchemaDeprecates() throws Exception {
        WorldMap clash = MapGenerator.generate(33);
        RunRecording accidents = RunRecording.of(clash, 33, Set.of(Fault.TARGET_LANE_CHECK_SKIPPED), BuiltinCar.FACTORY);
        RunRecording excused = RunRecording.of(MapGenerator.generate(60), 60, Set.of(Fault.TARGET_LANE_CHECK_SKIPPED),
                BuiltinCar.FACTORY);
        RunRecording traffic = RunRecording.of(MapGenerator.generate(1), 1, Set.of(Fault.ONCOMING_AT_HALF_SPEED),
                BuiltinCar.FACTORY);
        assertTrue(!accidents.accidents().isEmpty() && !excused.excused().isEmpty() && !traffic.traffic().isEmpty(),
                "the runs no longer have an accident, an excused contact and a contact between other vehicles");
        for (ScenarioVersion v : ScenarioVersion.values()) {
            Deprecations deprecated = Deprecations.of(AsamSchemas.file(v));
            List<String> documents = List.of(OpenScenario.situation(clash, "map.xodr", v),
                    OpenScenario.recording(accidents, Optional.of(accidents.accidents().get(0)), "map.xodr", v),
                    OpenScenario.recording(excused, "map.xodr", v), OpenScenario.recording(traffic, "map.xodr", v));
            for (String document : documents) {
                assertEquals(List.of(), deprecated.in(document).stream().distinct().toList(), "OpenSCENARIO " + v.label());
            }
        }
    }

    @Test
    void theWalkFindsADeprecatedElementAttributeAndValue() throws Exception {
        Deprecations deprecated = Deprecations.of(AsamSchemas.file(ScenarioVersion.V1_3));
        String recording = OpenScenario.recording(RunRecording.of(MapGenerator.generate(33), 33,
                Set.of(Fault.TARGET_LANE_CHECK_SKIPPED), BuiltinCar.FACTORY), "map.xodr", ScenarioVersion.V1_0);
        // 1.0's way, read by 1.3's schema: a trajectory straight in its action and parameters set as the run goes
        List<String> found = deprecated.in(recording.replace("revMinor=\"0\"", "revMinor=\"3\""));
        assertTrue(found.stream().anyMatch(f -> f.endsWith("FollowTrajectoryAction/Trajectory is deprecated where it stands"))
                && found.stream().anyMatch(f -> f.endsWith("GlobalAction/ParameterAction is deprecated where it stands")), found.toString());
        String withInteger = OpenScenario.situation(MapGenerator.generate(33), "map.xodr", ScenarioVersion.V1_3)
                .replace("<CatalogLocations/>", "<ParameterDeclarations><ParameterDeclaration name=\"n\" parameterType=\"integer\""
                        + " value=\"1\"/></ParameterDeclarations><CatalogLocations/>");
        assertTrue(deprecated.in(withInteger).stream().anyMatch(f -> f.endsWith("@parameterType=\"integer\" is a deprecated value")),
                deprecated.in(withInteger).toString());
    }
}
