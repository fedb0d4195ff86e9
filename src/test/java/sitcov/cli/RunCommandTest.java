package sitcov.cli;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class RunCommandTest {
    @TempDir
    Path dir;

    @Test
    void theSmokeExperimentGivesByteIdenticalRunsWithOneAndTwoThreads() throws Exception {
        Path one = dir.resolve("one");
        Path two = dir.resolve("two");
        CliRunner a = CliRunner.run("run", "smoke", "--threads", "1", "--out", one.toString());
        CliRunner b = CliRunner.run("run", "smoke", "--threads", "2", "--out", two.toString());
        assertEquals(0, a.exitCode(), a.err());
        assertEquals(0, b.exitCode(), b.err());
        byte[] runs = Files.readAllBytes(one.resolve("runs.csv"));
        assertArrayEquals(runs, Files.readAllBytes(two.resolve("runs.csv")), "runs.csv differs between 1 and 2 threads");
        assertArrayEquals(Files.readAllBytes(one.resolve("summary.csv")), Files.readAllBytes(two.resolve("summary.csv")));
        for (String file : new String[] {"summary.csv", "coverage-curve.csv", "timings.csv", "manifest.properties",
            "fig2-faults-per-map.png", "fig3-coverage.png", "table2.csv"}) {
            assertTrue(Files.size(one.resolve(file)) > 0, file);
        }
        assertTrue(Files.readString(one.resolve("manifest.properties")).contains("budget=ticks"));
        assertTrue(a.out().contains("Results in " + one), a.out());
        // both methods ran maps: a coverage row and a random row
        String csv = new String(runs);
        assertTrue(csv.contains("\ncoverage,") && csv.contains("\nrandom,"));
    }

    @Test
    void resultsNeverOverwriteAFolderThatHasFiles() throws Exception {
        Files.writeString(dir.resolve("keep.txt"), "mine");
        CliRunner r = CliRunner.run("run", "smoke", "--out", dir.toString());
        assertEquals(2, r.exitCode());
        assertTrue(r.err().contains("not an empty folder"), r.err());
        assertEquals("mine", Files.readString(dir.resolve("keep.txt")));
    }

    @Test
    void anUnknownPresetNamesWhereThePresetsAre() {
        CliRunner r = CliRunner.run("run", "no-such-preset");
        assertEquals(2, r.exitCode());
        assertTrue(r.err().contains("experiments/"), r.err());
    }
}
