package sitcov.cli;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.stream.Stream;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.MethodOrderer;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestInstance;
import org.junit.jupiter.api.TestMethodOrder;
import org.junit.jupiter.api.io.TempDir;
import sitcov.recording.Recording;
import sitcov.recording.RecordingFile;
import sitcov.results.ResultsFolder;
import sitcov.results.ResultsRows;

/**
 * A folder of a controller program (the Python example) keeps the commands of its failing runs, and
 * everything that shows a failure works from them once the program is gone.
 */
@TestInstance(TestInstance.Lifecycle.PER_CLASS)
@TestMethodOrder(MethodOrderer.OrderAnnotation.class) // the program is deleted last
class RecordedRunsOfAControllerProgramTest {
    private Path dir;
    private Path program;
    private Path preset;
    private Path whole;
    /** Each recording's trace, as simulate wrote it running the program live. */
    private final Map<String, byte[]> liveTraces = new TreeMap<>();

    @BeforeAll
    void runTheProgramOnceWholeAndTraceItsRecordedRunsLive(@TempDir Path tmp) throws Exception {
        dir = tmp;
        Assumptions.assumeTrue("true".equals(System.getenv("CI")) || python3Runs(),
                "python3 is not installed here: the Python example controller is not tested");
        program = dir.resolve("controller");
        Files.createDirectories(program);
        for (String f : List.of("route_driver.py", "sitcov_client.py")) {
            Files.copy(Path.of("experiments/controllers", f), program.resolve(f));
        }
        String driver = "exec:python3 " + program.resolve("route_driver.py");
        preset = dir.resolve("byo-tiny.properties");
        // late-brake as the reference has failures of its own; blind-pass fails where it does not on one map.
        // to-end: the variant's runs are recorded whole, so their traces compare whole with live ones
        Files.writeString(preset, "master_seed=11\ncandidates=8\nreplications=1\nbudget=ticks\ndrivers=random\n"
                + "grid=experiments/paper-grid.txt\ncontroller=" + driver + " --bug late-brake\nvariants=" + driver
                + " --bug blind-pass\nfaulty_runs=to-end\n");
        whole = dir.resolve("whole");
        CliRunner r = CliRunner.run("run", preset.toString(), "--out", whole.toString(), "--threads", "2");
        assertEquals(ExitCode.OK, r.exitCode(), r.err());
        for (Path rec : recordings(whole)) {
            Recording header = RecordingFile.read(rec);
            String controller = driver + (header.key().variant() == Recording.RunKey.REFERENCE ? " --bug late-brake" : " --bug blind-pass");
            Path trace = dir.resolve("live-" + rec.getFileName() + ".csv");
            CliRunner live = CliRunner.run("simulate", "--seed", Long.toString(header.externalSeed()), "--internal-seed",
                    Long.toString(header.internalSeed()), "--controller", controller, "--trace", trace.toString());
            assertEquals(ExitCode.OK, live.exitCode(), live.err());
            liveTraces.put(rec.getFileName().toString(), Files.readAllBytes(trace));
        }
    }

    private static List<Path> recordings(Path folder) throws Exception {
        try (Stream<Path> files = Files.list(folder.resolve(ResultsFolder.RECORDINGS))) {
            return files.sorted().toList();
        }
    }

    @Test
    @Order(2)
    void everyFailureAndFindingIsRecordedAndReplaysToTheLiveTraceByteForByteWithTheProgramGone() throws Exception {
        List<ResultsRows.Row> rows = ResultsRows.all(whole);
        long found = rows.stream().filter(row -> row.outcome().map(o -> o.detection().found()).orElse(false)).count();
        assertTrue(found > 0, "the planted bug is found on these maps, so there is something to record");
        // every found row has its own recording and its reference's
        for (ResultsRows.Row row : rows) {
            if (row.outcome().map(o -> o.detection().found()).orElse(false)) {
                assertTrue(sitcov.recording.FolderRecordings.has(whole, row), "row " + row.number() + " is recorded");
            }
        }
        long own = Files.readAllLines(whole.resolve(ResultsFolder.OWN_FAILURES)).size() - 1;
        assertTrue(own > 0, "the reference fails by itself on these maps");
        assertTrue(liveTraces.size() >= 2 * found && liveTraces.size() <= 2 * found + own,
                "the found runs, their references and the reference's own failures, nothing more: " + liveTraces.keySet());
        deleteProgram();
        for (Path rec : recordings(whole)) {
            Recording header = RecordingFile.read(rec);
            Path trace = dir.resolve("replayed-" + rec.getFileName() + ".csv");
            CliRunner replayed = CliRunner.run("simulate", "--seed", Long.toString(header.externalSeed()), "--commands",
                    rec.toString(), "--trace", trace.toString());
            assertEquals(ExitCode.OK, replayed.exitCode(), replayed.err());
            assertArrayEquals(liveTraces.get(rec.getFileName().toString()), Files.readAllBytes(trace),
                    rec.getFileName() + " replays to the live run's trace");
        }
        for (ResultsRows.Row row : rows) {
            if (sitcov.recording.FolderRecordings.has(whole, row)) {
                CliRunner replay = CliRunner.run("replay", whole.toString(), "--row", Integer.toString(row.number()),
                        "--png", dir.resolve("row-" + row.number() + ".png").toString(), "--gif",
                        dir.resolve("row-" + row.number() + ".gif").toString());
                assertEquals(ExitCode.OK, replay.exitCode(), replay.err());
                assertTrue(replay.out().contains("replays exactly as runs.csv recorded it, from its recorded commands"), replay.out());
                assertTrue(Files.size(dir.resolve("row-" + row.number() + ".gif")) > 0);
            }
        }
        everyFailureAndFindingIsPicturedInTheReportAndPaintedByTheViewer(rows);
        List<List<String>> printed = PrintedCommands.of(whole, dir.resolve("printed"));
        assertTrue(printed.size() >= own + found, "own-failures.csv and the report print a command for each: " + printed);
        Files.createDirectories(dir.resolve("printed"));
        for (List<String> command : printed) {
            CliRunner run = CliRunner.run(command.toArray(String[]::new));
            assertEquals(ExitCode.OK, run.exitCode(), "printed: " + command + "\n" + run.err());
        }
        CliRunner export = CliRunner.run("export", whole.toString(), "--found", "--out", dir.resolve("export").toString());
        assertEquals(ExitCode.OK, export.exitCode(), export.err());
        assertEquals(1 + found, Files.readAllLines(dir.resolve("export").resolve("index.csv")).size());
        // and what it wrote is as valid as a builtin folder's export
        try (Stream<Path> files = Files.list(dir.resolve("export"))) {
            List<Path> written = files.filter(f -> f.toString().endsWith(".xodr") || f.toString().endsWith(".xosc")).toList();
            assertTrue(written.stream().anyMatch(f -> f.toString().endsWith("-run.xosc")), "a recorded run among " + written);
            for (Path f : written) {
                sitcov.export.AsamSchemas.assertValid(f.toString().endsWith(".xodr") ? sitcov.export.AsamSchemas.openDrive()
                        : sitcov.export.AsamSchemas.openScenario(sitcov.export.ScenarioVersion.V1_0), Files.readString(f),
                        f.getFileName().toString());
            }
        }
    }

    @Test
    @Order(1)
    void aRunKilledAndResumedKeepsTheSameRecordingsByteForByte() throws Exception {
        Path folder = dir.resolve("killed");
        String classes = Path.of("target", "classes").toAbsolutePath() + java.io.File.pathSeparator
                + Path.of("target", "test-classes").toAbsolutePath();
        Process dying = new ProcessBuilder(ProcessHandle.current().info().command().orElse("java"), "-cp", classes,
                DyingRun.class.getName(), preset.toString(), folder.toString(), "3")
                .redirectErrorStream(true).redirectOutput(dir.resolve("dying.log").toFile()).start();
        assertEquals(DyingRun.KILLED, dying.waitFor(), "the run died on its third map: " + Files.readString(dir.resolve("dying.log")));
        assertTrue(Files.exists(folder.resolve(ResultsFolder.RECORDINGS)), "it had recorded failures before it died");
        // a kill in the middle of writing a recording leaves its temporary copy
        Path dirOf = folder.resolve(ResultsFolder.RECORDINGS);
        Files.createDirectories(dirOf);
        Files.writeString(dirOf.resolve(".r0-random-m7-ref.jsonl.gz1234.tmp"), "half");
        CliRunner resumed = CliRunner.run("run", "--resume", folder.toString(), "--threads", "2");
        assertEquals(ExitCode.OK, resumed.exitCode(), resumed.err());
        List<String> names = new ArrayList<>();
        for (Path rec : recordings(whole)) {
            names.add(rec.getFileName().toString());
            assertArrayEquals(Files.readAllBytes(rec), Files.readAllBytes(dirOf.resolve(rec.getFileName())),
                    rec.getFileName() + " is the same after a kill and a resume");
        }
        assertEquals(names, recordings(folder).stream().map(p -> p.getFileName().toString()).toList(),
                "the same recordings, and the kill's temporary file swept");
        assertArrayEquals(Files.readAllBytes(whole.resolve(ResultsFolder.RUNS)),
                Files.readAllBytes(folder.resolve(ResultsFolder.RUNS)));
    }

    /** With the program gone: the report drawn again pictures every own failure and finding, and view paints every recorded row. */
    private void everyFailureAndFindingIsPicturedInTheReportAndPaintedByTheViewer(List<ResultsRows.Row> rows)
            throws Exception {
        try (Stream<Path> old = Files.list(whole.resolve(ResultsFolder.REPLAYS))) {
            for (Path f : old.toList()) {
                Files.delete(f);
            }
        }
        CliRunner report = CliRunner.run("report", whole.toString());
        assertEquals(ExitCode.OK, report.exitCode(), report.err());
        String html = Files.readString(whole.resolve(ResultsFolder.REPORT));
        List<String> expected = new ArrayList<>();
        java.util.Set<Integer> firstOf = new java.util.HashSet<>();
        for (ResultsRows.Row row : rows) {
            boolean own = row.variant().isEmpty() && sitcov.analysis.OwnFailures.failed(row.map());
            boolean found = row.outcome().map(o -> o.detection().found()).orElse(false);
            if (own || found && !firstOf.add(row.variant().get().id())) {
                expected.add("replays/row-" + row.number() + ".png");
            } else if (found) {
                expected.add("replays/fault-" + row.variant().get().id() + ".png");
            }
        }
        assertTrue(expected.size() > 2 && expected.stream().anyMatch(n -> n.contains("row-")),
                "the case this test needs: own failures and findings beyond each variant's first, " + expected);
        for (String name : expected) {
            assertTrue(Files.isRegularFile(whole.resolve(name)), name + " is drawn without the program");
            assertTrue(html.contains("<img loading=\"lazy\" src=\"" + name + "\""), name + " is in report.html");
        }
        try (Stream<Path> drawn = Files.list(whole.resolve(ResultsFolder.REPLAYS))) {
            assertEquals(expected.size(), drawn.count(), "nothing but the failures and findings is pictured");
        }
        for (ResultsRows.Row row : rows) {
            if (sitcov.recording.FolderRecordings.has(whole, row)) {
                Path png = dir.resolve("view-row-" + row.number() + ".png");
                CliRunner view = CliRunner.run("view", whole.toString(), "--row", Integer.toString(row.number()), "--png",
                        png.toString());
                assertEquals(ExitCode.OK, view.exitCode(), view.err());
                assertEquals(row.variant().isEmpty() ? 1 : 2, Math.round(javax.imageio.ImageIO.read(png.toFile()).getWidth()
                        / (double) sitcov.render.MapRenderer.imageSize(sitcov.render.MapRenderer.DEFAULT_SCALE).width),
                        "row " + row.number() + " is painted in a pane per run");
            }
        }
    }

    private void deleteProgram() throws Exception {
        try (Stream<Path> files = Files.list(program)) {
            for (Path f : files.toList()) {
                Files.delete(f);
            }
        }
        Files.delete(program);
    }

    private static boolean python3Runs() {
        try {
            return new ProcessBuilder("python3", "--version").start().waitFor() == 0;
        } catch (java.io.IOException | InterruptedException e) {
            return false;
        }
    }
}
