package sitcov.cli;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import sitcov.builtin.BuiltinCar;
import sitcov.drivers.Drivers;
import sitcov.experiment.ExperimentConfig;
import sitcov.experiment.ExperimentEvent;
import sitcov.experiment.ExperimentRunner;
import sitcov.experiment.Shard;
import sitcov.report.ResultsRecorder;
import sitcov.results.Manifest;
import sitcov.results.ResultsFolder;

class ResumeCommandTest {
    @TempDir
    Path dir;

    /** Starts the preset into {@code folder} as run does, and stops it as a kill would once {@code maps} maps were judged. */
    static ExperimentConfig interrupt(String preset, Path folder, int maps) throws Exception {
        ExperimentConfig config = Preset.read(Path.of(preset), null, Drivers.standard()).config();
        ResultsRecorder recorder = ResultsRecorder.create(folder, new Manifest(config, Version.current(), Shard.WHOLE,
                false, false), Map.of(), System::nanoTime, BuiltinCar.FACTORY);
        ExperimentRunner[] runner = new ExperimentRunner[1];
        int[] judged = {0};
        runner[0] = new ExperimentRunner(config, Drivers.standard(), Shard.WHOLE, recorder.journal(), 2, System::nanoTime,
                List.of(recorder, e -> {
                    if (e instanceof ExperimentEvent.MapJudged && ++judged[0] == maps) {
                        runner[0].halt();
                    }
                }), BuiltinCar.SOURCE);
        assertFalse(runner[0].run(), "the run was meant to stop after " + maps + " maps");
        recorder.close();
        return config;
    }

    @Test
    void aRunStoppedAfterAnyNumberOfMapsResumesToTheSameBytes() throws Exception {
        Path whole = ResultsFolders.tinyReference();
        int total = Files.readAllLines(whole.resolve(ResultsFolder.TIMINGS)).stream().filter(l -> l.contains(",map,"))
                .toList().size();
        for (int k : new int[] {1, 9, total - 1}) {
            Path folder = dir.resolve("stopped-after-" + k);
            interrupt(ResultsFolders.TINY, folder, k);
            String manifest = Files.readString(folder.resolve(ResultsFolder.MANIFEST));
            assertTrue(manifest.contains("\ncomplete=false\n"), "a stopped run says it is incomplete: " + manifest);
            long journaled = Files.readAllLines(folder.resolve(ResultsFolder.RUNS)).stream()
                    .filter(l -> l.contains(",NONE,")).count();
            assertEquals(k, journaled, "maps in runs.csv when stopped after " + k);
            String firstTiming = Files.readAllLines(folder.resolve(ResultsFolder.TIMINGS)).get(1);

            CliRunner r = CliRunner.run("run", "--resume", folder.toString(), "--threads", "1");
            assertEquals(0, r.exitCode(), r.err());
            assertTrue(r.err().contains("resumed with " + k + " maps judged before"), r.err());
            ResultsFolders.assertSameResults(whole, folder);
            assertTrue(Files.readAllLines(folder.resolve(ResultsFolder.TIMINGS)).contains(firstTiming),
                    "the journaled map keeps the time it took: " + firstTiming);
        }
    }

    @Test
    void whatTheKillCutShortIsJudgedAgainAndTheTemporaryFilesItLeftAreSwept() throws Exception {
        Path folder = dir.resolve("cut");
        interrupt(ResultsFolders.TINY, folder, 5);
        Path runs = folder.resolve(ResultsFolder.RUNS);
        List<String> lines = Files.readAllLines(runs);
        // the kill struck in the middle of the fifth map's block: its last row is half written
        String cut = String.join("\n", lines.subList(0, lines.size() - 1)) + "\n"
                + lines.get(lines.size() - 1).substring(0, 20);
        Files.writeString(runs, cut, StandardCharsets.UTF_8);
        Files.writeString(folder.resolve(ResultsFolder.DRIVERS), "0,coverage-fil", StandardOpenOption.APPEND);
        // a kill while a file was being written whole leaves its temporary copy beside it
        Files.writeString(folder.resolve(".runs.csv8351.tmp"), "0,coverage-filter,0,");
        Files.writeString(folder.resolve(".manifest.properties12.tmp"), "# sitcov");

        CliRunner r = CliRunner.run("run", "--resume", folder.toString());
        assertEquals(0, r.exitCode(), r.err());
        assertTrue(r.err().contains("resumed with 4 maps judged before"), r.err());
        ResultsFolders.assertSameResults(ResultsFolders.tinyReference(), folder);
    }

    @Test
    void aResumedWallClockBudgetSaysSoInTheManifest() throws Exception {
        Path preset = dir.resolve("wall.properties");
        Files.writeString(preset, Files.readString(Path.of(ResultsFolders.TINY)).replace("budget=ticks", "budget=wall-clock")
                .replace("replications=3", "replications=1"));
        Path folder = dir.resolve("wall");
        interrupt(preset.toString(), folder, 3);
        CliRunner r = CliRunner.run("run", "--resume", folder.toString());
        assertEquals(0, r.exitCode(), r.err());
        String manifest = Files.readString(folder.resolve(ResultsFolder.MANIFEST));
        assertTrue(manifest.contains("\nresumed=true\n") && manifest.contains("\ncomplete=true\n"), manifest);
        assertTrue(Files.readString(folder.resolve(ResultsFolder.DRIVERS)).contains(",random,")
                && Files.readString(folder.resolve(ResultsFolder.DRIVERS)).contains(",wall-clock,"));
    }

    @Test
    void aCompleteFolderOrOneThatIsNoResultsFolderIsNotResumed() throws Exception {
        CliRunner done = CliRunner.run("run", "--resume", ResultsFolders.tinyReference().toString());
        assertEquals(2, done.exitCode());
        assertTrue(done.err().contains("is complete already"), done.err());
        CliRunner empty = CliRunner.run("run", "--resume", dir.toString());
        assertEquals(2, empty.exitCode());
        assertTrue(empty.err().contains("is not a results folder"), empty.err());
        CliRunner both = CliRunner.run("run", ResultsFolders.TINY, "--resume", dir.toString());
        assertEquals(2, both.exitCode());
        assertTrue(both.err().contains("--resume DIR takes everything from DIR's manifest"), both.err());
    }

    @Test
    void anUnfinishedFolderWhoseManifestWasEditedIsNotResumedIntoAMixOfBoth() throws Exception {
        Path stopped = dir.resolve("stopped");
        interrupt(ResultsFolders.TINY, stopped, 9);
        List<String[]> edits = List.of(new String[] {"candidates=12", "candidates=13", "candidates"},
                new String[] {"drivers=coverage-filter,random\n", "drivers=random,coverage-filter\n", "drivers"},
                new String[] {"budget=ticks", "budget=wall-clock", "budget"},
                new String[] {"faulty_runs=until-verdict", "faulty_runs=to-end", "faulty_runs"});
        for (String[] e : edits) {
            Path folder = dir.resolve("edited-" + e[2]);
            ResultsFolders.copy(stopped, folder);
            Path manifest = folder.resolve(ResultsFolder.MANIFEST);
            String text = Files.readString(manifest);
            assertTrue(text.contains("\n" + e[0]), e[0]);
            Files.writeString(manifest, text.replace("\n" + e[0], "\n" + e[1]));
            byte[] runs = Files.readAllBytes(folder.resolve(ResultsFolder.RUNS));

            CliRunner r = CliRunner.run("run", "--resume", folder.toString());
            assertEquals(ExitCode.USAGE, r.exitCode(), r.out());
            assertTrue(r.err().contains(manifest + ": " + e[2] + " was changed after sitcov wrote it"), r.err());
            assertArrayEquals(runs, Files.readAllBytes(folder.resolve(ResultsFolder.RUNS)), "the journal is left as it was");
        }
    }

    @Test
    void aFolderHoldingOnlyTheLockOfAKilledStartHasOneWayOut() throws Exception {
        Path folder = dir.resolve("lock-only");
        Files.createDirectories(folder);
        Files.writeString(folder.resolve(ResultsFolder.LOCK), "");
        Files.writeString(folder.resolve(".runs.csv99.tmp"), "replication,dri");
        CliRunner resume = CliRunner.run("run", "--resume", folder.toString());
        assertEquals(ExitCode.USAGE, resume.exitCode());
        assertTrue(resume.err().contains("holds no results: the run that made it was stopped before it wrote any; start it"
                + " again with 'run PRESET --out " + folder + "'"), resume.err());
        CliRunner again = CliRunner.run("run", ResultsFolders.TINY, "--replications", "1", "--out", folder.toString());
        assertEquals(0, again.exitCode(), again.err());
        assertTrue(Files.readString(folder.resolve(ResultsFolder.MANIFEST)).contains("\ncomplete=true\n"));
        assertFalse(Files.exists(folder.resolve(".runs.csv99.tmp")), "the killed start's temporary file is swept");
    }
}
