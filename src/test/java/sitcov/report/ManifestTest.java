package sitcov.report;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import sitcov.coverage.GridDefinition;
import sitcov.experiment.AnalysisPlan;
import sitcov.experiment.BudgetKind;
import sitcov.experiment.Direction;
import sitcov.experiment.ExperimentConfig;
import sitcov.experiment.FaultyRuns;
import sitcov.experiment.Measure;
import sitcov.experiment.Shard;
import sitcov.faults.FaultSet;

class ManifestTest {
    @TempDir
    Path dir;

    @Test
    void theDeclaredAnalysisIsRecordedAndReadBack() throws Exception {
        AnalysisPlan plan = new AnalysisPlan(Measure.DISCOVERY_AREA, List.of("random", "coverage-filter"), Direction.HIGHER,
                Map.of(Measure.DISCOVERY_AREA, 0.05, Measure.FAULTS_FOUND, 2.0));
        ExperimentConfig config = new ExperimentConfig("declared", 3, 10, 2, FaultSet.parse("19"), BudgetKind.TICKS,
                GridDefinition.paper(), List.of("coverage-filter", "random"), List.of(), 100, FaultyRuns.UNTIL_VERDICT, plan);
        new Manifest(config, "test", Shard.WHOLE, true, false).write(dir);
        String text = Files.readString(dir.resolve(ResultsFolder.MANIFEST));
        assertTrue(text.contains("primary_drivers=random,coverage-filter\n"), text);
        assertTrue(text.contains("margin_discovery_area=0.05\n"), text);
        assertTrue(text.contains("margin_cells_covered=5\n"), "defaults are written too: " + text);
        assertEquals(plan, Manifest.read(dir).config().analysis());
    }

    @Test
    void aFolderWrittenBeforeTheAnalysisWasDeclaredIsJudgedByTheDefaults() throws Exception {
        ExperimentConfig config = new ExperimentConfig("older", 3, 10, 2, FaultSet.parse("19"), BudgetKind.TICKS,
                GridDefinition.paper(), List.of("coverage-filter", "random", "every-other"), List.of(), 100,
                FaultyRuns.UNTIL_VERDICT);
        new Manifest(config, "test", Shard.WHOLE, true, false).write(dir);
        Path manifest = dir.resolve(ResultsFolder.MANIFEST);
        Files.writeString(manifest, Files.readString(manifest).replaceAll("(?m)^(primary|margin)_.*\\n", ""));
        AnalysisPlan read = Manifest.read(dir).config().analysis();
        assertEquals(AnalysisPlan.defaults(config.drivers()), read);
        assertEquals(List.of("coverage-filter", "random"), read.primaryDrivers());
    }
}
