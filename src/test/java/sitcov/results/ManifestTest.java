package sitcov.results;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
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
import sitcov.experiment.Measure;
import sitcov.experiment.Shard;
import sitcov.faults.FaultSet;
import sitcov.judge.FaultyRuns;

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
        // as written then: no analysis keys, and no checks
        Files.writeString(manifest, Files.readString(manifest).replaceAll("(?m)^((primary|margin)_|checks=).*\\n", ""));
        assertFalse(Manifest.read(dir).checked(), "a manifest without checks is read as one written before them");
        AnalysisPlan read = Manifest.read(dir).config().analysis();
        assertEquals(AnalysisPlan.defaults(config.drivers()), read);
        assertEquals(List.of("coverage-filter", "random"), read.primaryDrivers());
    }

    @Test
    void theControllerIsRecordedOnlyWhenItIsNotTheBuiltinCarAndIsPartOfTheExperimentsIdentity() throws Exception {
        ExperimentConfig builtin = new ExperimentConfig("ctl", 3, 10, 2, FaultSet.parse("19"), BudgetKind.TICKS,
                GridDefinition.paper(), List.of("coverage-filter", "random"), List.of(), 100, FaultyRuns.UNTIL_VERDICT);
        new Manifest(builtin, "test", Shard.WHOLE, true, false).write(dir);
        assertFalse(Files.readString(dir.resolve(ResultsFolder.MANIFEST)).contains("controller="),
                "folders of the builtin car read as those written before controllers had a name");
        assertEquals(ExperimentConfig.BUILTIN, Manifest.read(dir).config().controller());

        ExperimentConfig served = builtin.withController("exec:java -cp target/classes sitcov.cli.Main controller builtin");
        Path other = dir.resolve("served");
        Files.createDirectories(other);
        new Manifest(served, "test", Shard.WHOLE, true, false).write(other);
        assertEquals(served.controller(), Manifest.read(other).config().controller());
        assertFalse(new Manifest(builtin, "test", Shard.WHOLE, true, false).identity()
                .equals(new Manifest(served, "test", Shard.WHOLE, true, false).identity()), "another controller is another experiment");
    }

    private Path written() throws Exception {
        ExperimentConfig config = new ExperimentConfig("edited", 3, 10, 2, FaultSet.parse("19"), BudgetKind.TICKS,
                GridDefinition.paper(), List.of("coverage-filter", "random"), List.of(), 100, FaultyRuns.UNTIL_VERDICT);
        new Manifest(config, "test", Shard.WHOLE, false, false).write(dir);
        return dir.resolve(ResultsFolder.MANIFEST);
    }

    private String refusal(Path manifest, String from, String to) throws Exception {
        String text = Files.readString(manifest);
        assertTrue(text.contains(from), from + " in " + text);
        Files.writeString(manifest, text.replace(from, to));
        try {
            return assertThrows(IllegalArgumentException.class, () -> Manifest.read(dir)).getMessage();
        } finally {
            Files.writeString(manifest, text);
        }
    }

    @Test
    void aKeyChangedByHandIsRefusedNamingIt() throws Exception {
        Path manifest = written();
        assertEquals(3, Manifest.read(dir).config().masterSeed(), "the untouched manifest reads");
        Map<String, String[]> edits = Map.of(
                "master_seed", new String[] {"\nmaster_seed=3\n", "\nmaster_seed=4\n"},
                "replications", new String[] {"\nreplications=2\n", "\nreplications=20\n"},
                "candidates", new String[] {"\ncandidates=10\n", "\ncandidates=11\n"},
                "budget", new String[] {"\nbudget=ticks\n", "\nbudget=wall-clock\n"},
                "faulty_runs", new String[] {"\nfaulty_runs=until-verdict\n", "\nfaulty_runs=to-end\n"},
                "drivers", new String[] {"\ndrivers=coverage-filter,random\n", "\ndrivers=random,coverage-filter\n"});
        for (Map.Entry<String, String[]> e : edits.entrySet()) {
            String message = refusal(manifest, e.getValue()[0], e.getValue()[1]);
            assertTrue(message.startsWith(manifest + ": " + e.getKey() + " was changed after sitcov wrote it"), message);
            assertTrue(message.endsWith("put the manifest back as it was, or run the experiment again into a new folder"),
                    message);
        }
    }

    @Test
    void anAddedOrRemovedLineIsRefusedSayingWhere() throws Exception {
        Path manifest = written();
        String added = refusal(manifest, "\nmaster_seed=3\n", "\nmaster_seed=3\nmaster_seed_note=mine\n");
        assertTrue(added.contains(": master_seed_note was added or changed"), added);
        String removed = refusal(manifest, "\nmargin_maps_run=5\n", "\n");
        assertTrue(removed.contains(": a line before 'margin_prop_map_all_fault' was removed"), removed);
        String comment = Files.readString(manifest) + "# a note of mine\n";
        Files.writeString(manifest, comment);
        assertEquals(3, Manifest.read(dir).config().masterSeed(), "a comment changes nothing that is checked");
    }

    @Test
    void completeIsTheOneLineTheChecksLeaveToTheTool() throws Exception {
        Path manifest = written();
        Files.writeString(manifest, Files.readString(manifest).replace("complete=false", "complete=true"));
        assertTrue(Manifest.read(dir).complete());
        assertTrue(Manifest.read(dir).checked());
    }
}
