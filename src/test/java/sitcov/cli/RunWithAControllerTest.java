package sitcov.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class RunWithAControllerTest {
    @Test
    void aControllerProgramThatFailsItsHandshakeStopsTheRunBeforeAnyFolderIsMade(@TempDir Path dir) {
        Path out = dir.resolve("never");
        CliRunner r = CliRunner.run("run", "smoke", "--out", out.toString(), "--controller", "exec:sh -c 'exit 3'");
        assertEquals(ExitCode.USAGE, r.exitCode(), r.err());
        assertTrue(r.err().contains("failed the handshake") && r.err().contains("sh -c"), r.err());
        assertFalse(Files.exists(out), "nothing is written for a controller that cannot start");
    }

    @Test
    void anExperimentOnAnotherControllerKeepsItInTheManifestAndReplaysItsFindingsFromTheirRecordings(@TempDir Path dir)
            throws Exception {
        Path out = dir.resolve("planted");
        CliRunner r = CliRunner.run("run", ResultsFolders.TINY, "--replications", "1", "--out", out.toString(),
                "--controller", "builtin:16", "--threads", "1");
        assertEquals(ExitCode.OK, r.exitCode(), r.err());
        assertTrue(Files.readString(out.resolve("manifest.properties")).contains("controller=builtin:16\n"));
        assertTrue(Files.list(out.resolve("recordings")).findAny().isPresent(), "the reference's failures are recorded");
        String report = Files.readString(out.resolve("report.html"));
        assertTrue(report.contains("<span>replay</span>") && !report.contains("<span>simulate</span>"),
                "the report's commands replay the recorded rows");
        // a row that passed is not recorded: replay names the command that runs its map with the folder's controller
        int passing = passingRow(out);
        CliRunner replay = CliRunner.run("replay", out.toString(), "--row", Integer.toString(passing));
        assertEquals(ExitCode.USAGE, replay.exitCode(), replay.out());
        assertTrue(replay.err().contains("--controller \"builtin:16\"") && replay.err().contains("simulate --seed "),
                replay.err());
    }

    /** The number of a row whose map has no recording: every run on it passed. */
    private static int passingRow(Path out) throws Exception {
        for (sitcov.results.ResultsRows.Row row : sitcov.results.ResultsRows.all(out)) {
            if (!sitcov.recording.FolderRecordings.has(out, row)) {
                return row.number();
            }
        }
        throw new AssertionError("every row of " + out + " is recorded");
    }

    @Test
    void aControllerThatNamesNothingIsRefusedWithWhatIsAccepted(@TempDir Path dir) {
        CliRunner r = CliRunner.run("run", "smoke", "--out", dir.resolve("x").toString(), "--controller", "python3 me.py");
        assertEquals(ExitCode.USAGE, r.exitCode());
        assertTrue(r.err().contains("builtin:FAULTS") && r.err().contains("exec:COMMAND"), r.err());
    }

    @Test
    void aProgramAndItsPlantedBugAreComparedByTheDifferentialOracle(@TempDir Path dir) throws Exception {
        org.junit.jupiter.api.Assumptions.assumeTrue("true".equals(System.getenv("CI")) || python3Runs(),
                "python3 is not installed here: the Python example controller is not tested");
        Path p = dir.resolve("byo.properties");
        String driver = "exec:python3 experiments/controllers/route_driver.py";
        Files.writeString(p, "master_seed=11\ncandidates=8\nreplications=1\nbudget=ticks\ndrivers=coverage-filter,random\n"
                + "grid=experiments/paper-grid.txt\ncontroller=" + driver + "\nvariants=" + driver + " --bug late-brake\n");
        Path out = dir.resolve("out");
        CliRunner r = CliRunner.run("run", p.toString(), "--out", out.toString(), "--threads", "2");
        assertEquals(ExitCode.OK, r.exitCode(), r.err());
        java.util.List<String> rows = Files.readAllLines(out.resolve("runs.csv"));
        java.util.List<String> header = java.util.List.of(rows.get(0).split(","));
        java.util.Set<String> found = new java.util.HashSet<>();
        for (String line : rows.subList(1, rows.size())) {
            String[] c = line.split(",", -1);
            if (c[header.indexOf("fault")].equals("1") && c[header.indexOf("detection")].equals("FOUND")) {
                found.add(c[header.indexOf("map")]); // a map both drivers ran is one map
                // the bug brakes late behind the traffic: what it adds are clashes with moving cars
                assertEquals("CLASHWITHOTHERCAR", c[header.indexOf("new_accident")], line);
                assertTrue(Long.parseLong(c[header.indexOf("clashwithothercar")]) > 0, line);
            }
        }
        assertFalse(found.isEmpty(), "on these maps the bug adds a clash: " + String.join("\n", rows));
        String verdict = Files.readString(out.resolve("verdict.txt"));
        assertTrue(verdict.contains("1 = route_driver.py-bug-late-brake (" + driver + " --bug late-brake)"), verdict);
        assertTrue(verdict.contains("variant 1 (route_driver.py-bug-late-brake): fails where the reference did not on "
                + found.size() + " of "), verdict);
        assertTrue(Files.isRegularFile(out.resolve("controller-1.log"))
                && Files.isRegularFile(out.resolve("controller-variant-1-1.log")), "each program's stderr is kept");
    }

    private static boolean python3Runs() {
        try {
            return new ProcessBuilder("python3", "--version").start().waitFor() == 0;
        } catch (java.io.IOException | InterruptedException e) {
            return false;
        }
    }
}
