package sitcov.report;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import sitcov.builtin.BuiltinCar;
import sitcov.coverage.GridDefinition;
import sitcov.drivers.Drivers;
import sitcov.experiment.BudgetKind;
import sitcov.experiment.Candidate;
import sitcov.experiment.ExperimentConfig;
import sitcov.experiment.ExperimentEvent;
import sitcov.experiment.ExperimentListener;
import sitcov.experiment.ExperimentRunner;
import sitcov.experiment.Journal;
import sitcov.experiment.MapId;
import sitcov.experiment.MapRun;
import sitcov.experiment.SeedPlan;
import sitcov.experiment.Shard;
import sitcov.faults.FaultSet;
import sitcov.judge.FaultyRuns;
import sitcov.results.FolderLock;
import sitcov.results.JournalFiles;
import sitcov.results.Manifest;
import sitcov.results.ResultsFolder;
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
        ResultsRecorder recorder = ResultsRecorder.create(dir, manifest, Map.of(), System::nanoTime, BuiltinCar.FACTORY);
        new ExperimentRunner(config, WITH_BUILDER, Shard.WHOLE, recorder.journal(), 1, System::nanoTime, List.of(recorder), BuiltinCar.SOURCE)
                .run();

        Journal journal = JournalFiles.read(dir, manifest);
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
                Map.of(), System::nanoTime, BuiltinCar.FACTORY);
        new ExperimentRunner(config, Drivers.standard(), Shard.WHOLE, recorder.journal(), 1, System::nanoTime,
                List.of(recorder), BuiltinCar.SOURCE).run();
        try (var files = Files.list(dir)) {
            for (Path f : files.toList()) {
                assertEquals("rw-r--r--", PosixFilePermissions.toString(Files.getPosixFilePermissions(f)), f.toString());
            }
        }
    }

    @Test
    void aKeptSituationFileDeletedOrChangedIsRefusedNamingIt() throws Exception {
        ExperimentConfig config = new ExperimentConfig("kept", 5, 6, 1, FaultSet.parse("19"), BudgetKind.TICKS,
                GridDefinition.paper(), List.of("builder"), List.of(), 6, FaultyRuns.UNTIL_VERDICT);
        ResultsRecorder recorder = ResultsRecorder.create(dir, new Manifest(config, "test", Shard.WHOLE, false, false),
                Map.of(), System::nanoTime, BuiltinCar.FACTORY);
        new ExperimentRunner(config, WITH_BUILDER, Shard.WHOLE, recorder.journal(), 1, System::nanoTime, List.of(recorder), BuiltinCar.SOURCE)
                .run();
        Path kept = ResultsFolder.situation(dir, "built-1");
        String text = Files.readString(kept);
        ResultsFinisher.report(dir, BuiltinCar.FACTORY);

        // a road moved by hand: "road 0 NORTH_SOUTH 55.06 ..." becomes "road 0 NORTH_SOUTH 550.06 ..."
        String edited = text.replaceFirst("(?m)^(road \\S+ \\S+ \\d+)", "$10");
        assertNotEquals(text, edited);
        Files.writeString(kept, edited);
        IllegalArgumentException changed = assertThrows(IllegalArgumentException.class, () -> ResultsFinisher.report(dir, BuiltinCar.FACTORY));
        assertTrue(changed.getMessage().startsWith(kept + " was changed after sitcov wrote it (it does not match the check in "
                + dir.resolve(ResultsFolder.RUNS) + ":"), changed.getMessage());

        Files.delete(kept);
        IllegalArgumentException missing = assertThrows(IllegalArgumentException.class, () -> ResultsFinisher.report(dir, BuiltinCar.FACTORY));
        assertTrue(missing.getMessage().startsWith(kept + " is missing, but " + dir.resolve(ResultsFolder.RUNS) + ":"),
                missing.getMessage());
        // a resume reads the journal the same way, and gives the folder up again when it refuses it
        Manifest unfinished = Manifest.read(dir).complete(false);
        IllegalArgumentException resumed = assertThrows(IllegalArgumentException.class,
                () -> ResultsRecorder.resume(dir, unfinished, Map.of(), System::nanoTime, BuiltinCar.FACTORY));
        assertTrue(resumed.getMessage().startsWith(kept + " is missing"), resumed.getMessage());

        Files.writeString(kept, text);
        ResultsFinisher.report(dir, BuiltinCar.FACTORY);
    }

    @Test
    void aSituationNameReusedByAnotherReplicationIsRefusedBeforeItReplacesTheFirstOnesFile() throws Exception {
        // a name without the replication in it: replication 1 builds "built-0" from another map than replication 0
        Map<Integer, Long> builtFrom = new ConcurrentHashMap<>();
        Drivers reusing = Drivers.standard().with("reusing", () -> session -> {
            while (session.budgetLeft()) {
                Candidate c = session.nextCandidate();
                if (c.runnable()) {
                    builtFrom.put(session.replication(), c.externalSeed());
                    session.run("built-0", MapGenerator.generate(c.externalSeed()));
                    return;
                }
            }
        });
        ExperimentConfig config = new ExperimentConfig("reused", 5, 6, 2, FaultSet.parse("19"), BudgetKind.TICKS,
                GridDefinition.paper(), List.of("reusing"), List.of(), 6, FaultyRuns.UNTIL_VERDICT);
        Path kept = ResultsFolder.situation(dir, "built-0");
        ResultsRecorder recorder = ResultsRecorder.create(dir, new Manifest(config, "test", Shard.WHOLE, false, false),
                Map.of(), System::nanoTime, BuiltinCar.FACTORY);
        // one thread: replication 0 runs first and keeps its file
        ExperimentRunner runner = new ExperimentRunner(config, reusing, Shard.WHOLE, recorder.journal(), 1,
                System::nanoTime, List.of(recorder), BuiltinCar.SOURCE);
        IllegalStateException e = assertThrows(IllegalStateException.class, runner::run);
        recorder.close();

        assertNotEquals(builtFrom.get(0), builtFrom.get(1), "the two replications built different maps");
        assertTrue(e.getMessage().contains(kept + " holds another situation of that name, from an earlier map of this"
                + " experiment; driver reusing in replication 1 may not replace it"), e.getMessage());
        assertEquals(MapGenerator.generate(builtFrom.get(0)), SituationFile.read(kept));
    }

    @Test
    void aShardWithNoReplicationsCompletesItsFolderAndSaysThereIsNothingToCompare() throws Exception {
        // two replications in three shards: shard 3/3 has none (run refuses it now; a folder an older version left remains)
        ExperimentConfig config = new ExperimentConfig("empty", 5, 3, 2, FaultSet.parse("19"), BudgetKind.TICKS,
                GridDefinition.paper());
        Shard third = new Shard(3, 3);
        ResultsRecorder recorder = ResultsRecorder.create(dir, new Manifest(config, "test", third, false, false), Map.of(),
                System::nanoTime, BuiltinCar.FACTORY);
        ExperimentRunner runner = new ExperimentRunner(config, Drivers.standard(), third, recorder.journal(), 1,
                System::nanoTime, List.of(recorder), BuiltinCar.SOURCE);
        assertEquals(List.of(), runner.replications());
        assertTrue(runner.run());
        recorder.close();
        assertTrue(ResultsRecorder.isComplete(dir));
        assertEquals(0, recorder.summary().results().size());
        assertTrue(Files.readString(dir.resolve(ResultsFolder.VERDICT)).startsWith("No replications in this folder (a shard"
                + " that got none), so nothing to compare"), Files.readString(dir.resolve(ResultsFolder.VERDICT)));
        assertEquals(1, Files.readAllLines(dir.resolve(ResultsFolder.RUNS)).size(), "runs.csv: its header alone");
    }

    @Test
    void aRunWhoseFolderWasDeletedStopsAtItsNextWrite() throws Exception {
        ExperimentConfig config = new ExperimentConfig("deleted", 5, 4, 1, FaultSet.parse("19"), BudgetKind.TICKS,
                GridDefinition.paper(), List.of("random"), List.of(), 4, FaultyRuns.UNTIL_VERDICT);
        Path folder = dir.resolve("results");
        ResultsRecorder recorder = ResultsRecorder.create(folder, new Manifest(config, "test", Shard.WHOLE, false, false),
                Map.of(), System::nanoTime, BuiltinCar.FACTORY);
        int[] judged = {0};
        // after the first judged map is journalled, the folder goes, as an 'rm -r' beside the run would take it
        ExperimentListener remover = event -> {
            if (event instanceof ExperimentEvent.MapJudged && judged[0]++ == 0) {
                try (var files = Files.walk(folder)) {
                    for (Path f : files.sorted(java.util.Comparator.reverseOrder()).toList()) {
                        Files.delete(f);
                    }
                } catch (java.io.IOException e) {
                    throw new java.io.UncheckedIOException(e);
                }
            }
        };
        ExperimentRunner runner = new ExperimentRunner(config, Drivers.standard(), Shard.WHOLE, recorder.journal(), 1,
                System::nanoTime, List.of(recorder, remover), BuiltinCar.SOURCE);
        FolderLock.Lost lost = assertThrows(FolderLock.Lost.class, runner::run);
        recorder.close();
        assertTrue(lost.getMessage().contains("the results folder " + folder + " was deleted"), lost.getMessage());
        assertEquals(1, judged[0], "nothing was judged into the void after the next write found the folder gone");
        assertFalse(Files.exists(folder), "and nothing made the folder again");
    }
}
