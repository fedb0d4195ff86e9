package sitcov.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import sitcov.judge.RunObserver;
import sitcov.oracle.Outcome;
import sitcov.recording.FolderRecordings;
import sitcov.results.ResultsFolder;
import sitcov.results.ResultsRows;

/** {@code --record all}: a folder keeps the recordings of the runs that pass too, and each replays as runs.csv has it. */
class RecordEveryRunTest {
    private static CliRunner versions(Path out, String... more) {
        List<String> args = new java.util.ArrayList<>(List.of("versions", "--reference", "builtin", "--variants",
                "builtin:19", "--maps", "3", "--threads", "2", "--out", out.toString()));
        args.addAll(List.of(more));
        return CliRunner.run(args.toArray(String[]::new));
    }

    /** A row whose run passed: the reference reached the Target without an accident, or the variant found nothing. */
    private static boolean passed(ResultsRows.Row row) {
        return row.outcome().map(o -> !o.detection().found() && o.run().outcome() == Outcome.TARGET_REACHED
                && o.run().accidents().stream().allMatch(n -> n == 0))
                .orElse(row.map().faultFree().outcome() == Outcome.TARGET_REACHED
                        && row.map().faultFree().accidents().stream().allMatch(n -> n == 0));
    }

    @Test
    void aPassingRunIsRecordedWithRecordAllAndNotWithoutAndReplaysToItsRecordedOutcome(@TempDir Path dir) throws Exception {
        Path all = dir.resolve("all");
        Path failures = dir.resolve("failures");
        CliRunner withAll = versions(all, "--record", "all");
        assertEquals(ExitCode.OK, withAll.exitCode(), withAll.err());
        CliRunner without = versions(failures);
        assertEquals(ExitCode.OK, without.exitCode(), without.err());
        List<ResultsRows.Row> rows = ResultsRows.all(all);
        List<ResultsRows.Row> passing = rows.stream().filter(RecordEveryRunTest::passed).toList();
        assertTrue(passing.stream().anyMatch(r -> r.variant().isEmpty()) && passing.stream().anyMatch(r -> r.variant()
                .isPresent()), "the case this test needs: passing rows of the reference and of the variant");
        for (ResultsRows.Row row : passing) {
            assertTrue(FolderRecordings.has(all, row), "row " + row.number() + " is recorded with --record all");
            assertFalse(Files.exists(FolderRecordings.file(failures, FolderRecordings.key(row, false))),
                    "row " + row.number() + " is not recorded without it");
            var map = ResultsRows.worldMap(all, row.map());
            var replayed = FolderRecordings.replay(all, row, map, RunObserver.NONE, RunObserver.NONE).orElseThrow();
            var run = row.variant().isEmpty() ? replayed.reference().result() : replayed.variant().orElseThrow().result();
            var recorded = row.outcome().map(o -> o.run()).orElse(row.map().faultFree());
            assertEquals(recorded.outcome(), run.outcome(), "row " + row.number() + " replays to its outcome");
            assertEquals(recorded.ticks(), run.ticks(), "row " + row.number() + " replays to its tick");
        }
        for (String table : List.of(ResultsFolder.RUNS, ResultsFolder.DRIVERS, ResultsFolder.VERDICT)) {
            org.junit.jupiter.api.Assertions.assertArrayEquals(Files.readAllBytes(failures.resolve(table)),
                    Files.readAllBytes(all.resolve(table)), table + " is the same whichever runs are recorded");
        }
        assertTrue(Files.readString(all.resolve(ResultsFolder.MANIFEST)).contains("\nrecordings=all\n"),
                "the manifest says so, for a resume to record as the run did");
        assertFalse(Files.readString(failures.resolve(ResultsFolder.MANIFEST)).contains("recordings="));
    }

    @Test
    void theReferenceAndTheVariantOfFaultZeroAreRecordedApart(@TempDir Path dir) throws Exception {
        // fault 0 is a variant whose id is 0: its recording must not take the reference's place
        Path out = dir.resolve("zero");
        CliRunner run = CliRunner.run("versions", "--reference", "builtin", "--variants", "builtin:0", "--maps", "2",
                "--threads", "2", "--out", out.toString(), "--record", "all");
        assertEquals(ExitCode.OK, run.exitCode(), run.err());
        List<ResultsRows.Row> rows = ResultsRows.all(out);
        assertTrue(rows.stream().anyMatch(r -> r.outcome().isPresent()
                        && r.outcome().get().run().ticks() != r.map().faultFree().ticks()),
                "the case this test needs: a run of fault 0 that differs from the reference's");
        for (ResultsRows.Row row : rows) {
            Path file = FolderRecordings.file(out, FolderRecordings.key(row, row.variant().isEmpty()));
            var header = sitcov.recording.RecordingFile.read(file);
            var recorded = row.outcome().map(o -> o.run()).orElse(row.map().faultFree());
            assertEquals(recorded.outcome(), header.outcome(), file.getFileName() + " holds row " + row.number() + "'s run");
            assertEquals(recorded.ticks(), header.ticks(), file.getFileName() + " holds row " + row.number() + "'s run");
        }
    }

    @Test
    void recordTakesFailuresOrAllAndIsRefusedWhereItHasNoMeaning(@TempDir Path dir) {
        CliRunner wrong = versions(dir.resolve("x"), "--record", "passes");
        assertEquals(ExitCode.USAGE, wrong.exitCode());
        assertTrue(wrong.err().contains("--record takes failures (the default: failing runs and findings) or all"),
                wrong.err());
        assertFalse(Files.exists(dir.resolve("x")), "nothing was written");
        CliRunner resume = CliRunner.run("run", "--resume", dir.toString(), "--record", "all");
        assertEquals(ExitCode.USAGE, resume.exitCode());
        assertTrue(resume.err().contains("drop --record"), resume.err());
        CliRunner campaign = CliRunner.run("run", "src/test/resources/presets/campaign-tiny.properties", "--record", "all",
                "--out", dir.resolve("c").toString());
        assertEquals(ExitCode.USAGE, campaign.exitCode());
        assertTrue(campaign.err().contains("is a campaign") && campaign.err().contains("drop --record"), campaign.err());
    }
}
