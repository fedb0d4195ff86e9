package sitcov.report;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import sitcov.coverage.GridDefinition;
import sitcov.experiment.BudgetKind;
import sitcov.experiment.Candidate;
import sitcov.experiment.Drivers;
import sitcov.experiment.ExperimentConfig;
import sitcov.experiment.FaultyRuns;
import sitcov.experiment.ExperimentRunner;
import sitcov.experiment.Journal;
import sitcov.experiment.MapId;
import sitcov.experiment.MapRun;
import sitcov.experiment.SeedPlan;
import sitcov.experiment.Shard;
import sitcov.faults.FaultSet;
import sitcov.world.MapGenerator;
import sitcov.world.SituationFile;
import sitcov.world.WorldMap;

class ResultsRecorderTest {
    @TempDir
    Path dir;

    /** A driver that builds its situations: here, the generated map of each runnable candidate, under a name. */
    private static final Drivers WITH_BUILDER = Drivers.standard().with("builder", () -> session -> {
        while (session.budgetLeft()) {
            Candidate c = session.nextCandidate();
            if (c.runnable() && c.index() < 3) {
                session.run("built-" + c.index(), MapGenerator.generate(c.externalSeed()));
            }
        }
    });

    @Test
    void aSituationADriverBuiltIsKeptInTheFolderAndNamedInRunsCsv() throws Exception {
        ExperimentConfig config = new ExperimentConfig("built", 5, 6, 1, FaultSet.parse("19"), BudgetKind.TICKS,
                GridDefinition.paper(), List.of("builder"), List.of(), 6, FaultyRuns.UNTIL_VERDICT);
        Manifest manifest = new Manifest(config, "test", Shard.WHOLE, false, false);
        ResultsRecorder recorder = ResultsRecorder.create(dir, manifest, Map.of(), System::nanoTime);
        new ExperimentRunner(config, WITH_BUILDER, Shard.WHOLE, recorder.journal(), 1, System::nanoTime, List.of(recorder))
                .run();

        Journal journal = JournalFiles.read(dir, config);
        List<MapRun> maps = journal.maps(0, "builder").stream().map(Journal.Entry::run).toList();
        assertTrue(maps.size() >= 2, "the builder ran " + maps.size() + " situations");
        for (MapRun m : maps) {
            MapId.Situation id = (MapId.Situation) m.map();
            WorldMap kept = SituationFile.read(ResultsFolder.situation(dir, id.name()));
            assertEquals(MapGenerator.generate(m.externalSeed()), kept, id.name());
            assertEquals(SeedPlan.internalSeed(5, id), m.internalSeed());
            assertEquals(-1, m.candidate());
            assertTrue(Files.readString(dir.resolve(ResultsFolder.RUNS)).contains(",situation:" + id.name() + ","));
        }
        assertTrue(ResultsRecorder.isComplete(dir));
    }

    @Test
    void resultFilesAreReadableByOthers() throws Exception {
        ExperimentConfig config = new ExperimentConfig("modes", 5, 3, 1, FaultSet.parse("19"), BudgetKind.TICKS,
                GridDefinition.paper(), List.of("random"), List.of(), 3, FaultyRuns.UNTIL_VERDICT);
        ResultsRecorder recorder = ResultsRecorder.create(dir, new Manifest(config, "test", Shard.WHOLE, false, false),
                Map.of(), System::nanoTime);
        new ExperimentRunner(config, Drivers.standard(), Shard.WHOLE, recorder.journal(), 1, System::nanoTime,
                List.of(recorder)).run();
        try (var files = Files.list(dir)) {
            for (Path f : files.toList()) {
                assertEquals("rw-r--r--", PosixFilePermissions.toString(Files.getPosixFilePermissions(f)), f.toString());
            }
        }
    }
}
