package sitcov.cli;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import sitcov.results.ResultsFolder;
import sitcov.results.SignedEdits;

/**
 * Folders written before runs.csv kept the near_* and rho_* columns, and the older rows of such a
 * folder this build resumed: their rows replay and export, their margins unknown rather than wrong.
 */
class FoldersWithoutMarginsTest {
    @TempDir
    Path dir;

    /** The folder as a build without margins (and so without recordings) wrote it, checks and all. */
    private static void asWrittenBeforeMargins(Path folder) throws IOException {
        Path recordings = folder.resolve(ResultsFolder.RECORDINGS);
        if (Files.isDirectory(recordings)) {
            try (Stream<Path> s = Files.walk(recordings)) {
                for (Path p : s.sorted(Comparator.reverseOrder()).toList()) {
                    Files.delete(p);
                }
            }
        }
        SignedEdits.withoutMargins(folder);
    }

    /** The rows (1 = first under the header) whose fault was FOUND, split by whether their margins are blank. */
    private static List<List<Integer>> foundRows(Path folder) throws IOException {
        List<String> lines = Files.readAllLines(folder.resolve(ResultsFolder.RUNS));
        int rho = List.of(lines.get(0).split(",", -1)).indexOf("rho_leaveroad");
        List<Integer> blank = new ArrayList<>();
        List<Integer> known = new ArrayList<>();
        for (int i = 1; i < lines.size(); i++) {
            if (lines.get(i).contains(",FOUND,")) {
                (rho < 0 || lines.get(i).split(",", -1)[rho].isEmpty() ? blank : known).add(i);
            }
        }
        return List.of(blank, known);
    }

    private void replaysAndExports(Path folder, int row) {
        CliRunner replay = CliRunner.run("replay", folder.toString(), "--row", Integer.toString(row), "--png",
                dir.resolve("row-" + row + ".png").toString());
        Path out = dir.resolve("export-" + row);
        CliRunner export = CliRunner.run("export", folder.toString(), "--row", Integer.toString(row), "--out", out.toString());
        assertAll(
                () -> assertEquals(ExitCode.OK, replay.exitCode(), "replay of row " + row + ": " + replay.err()),
                () -> assertTrue(replay.out().contains("Row " + row + " replays exactly"), replay.out()),
                () -> assertEquals(ExitCode.OK, export.exitCode(), "export of row " + row + ": " + export.err()),
                () -> assertTrue(Files.isDirectory(out), "export wrote " + out));
    }

    @Test
    void aRowOfAFolderWrittenBeforeMarginsWereKeptReplaysAndExports() throws Exception {
        Path old = dir.resolve("old");
        ResultsFolders.copy(ResultsFolders.tinyReference(), old);
        asWrittenBeforeMargins(old);
        String header = Files.readAllLines(old.resolve(ResultsFolder.RUNS)).get(0);
        assertFalse(header.contains("near_") || header.contains("rho_"), header);
        List<List<Integer>> rows = foundRows(old);
        assertFalse(rows.get(0).isEmpty(), "the tiny run finds its faults");
        replaysAndExports(old, rows.get(0).get(0));
    }

    @Test
    void aFolderResumedByThisBuildReplaysTheRowsTheOlderBuildWroteAndItsOwn() throws Exception {
        Path folder = dir.resolve("resumed");
        ResumeCommandTest.interrupt(ResultsFolders.TINY, folder, 6);
        asWrittenBeforeMargins(folder);
        CliRunner r = CliRunner.run("run", "--resume", folder.toString(), "--threads", "1");
        assertEquals(ExitCode.OK, r.exitCode(), r.err());
        List<List<Integer>> rows = foundRows(folder);
        assertFalse(rows.get(0).isEmpty(), "a row the older build wrote (margins blank) found its fault");
        assertFalse(rows.get(1).isEmpty(), "a row this build wrote (margins kept) found its fault");
        replaysAndExports(folder, rows.get(0).get(0));
        replaysAndExports(folder, rows.get(1).get(0));
    }

    @Test
    void aRowWhoseMarginsWereKeptIsStillHeldToThemAndTheMessageSaysSo() throws Exception {
        Path copy = dir.resolve("other-margins");
        ResultsFolders.copy(ResultsFolders.tinyReference(), copy);
        List<String> lines = Files.readAllLines(copy.resolve(ResultsFolder.RUNS));
        int rho = List.of(lines.get(0).split(",", -1)).indexOf("rho_leaveroad");
        int row = foundRows(copy).get(1).get(0);
        int faultFree = row;
        while (!lines.get(faultFree).contains(",NONE,")) {
            faultFree--;
        }
        // as another build would have written it: the fault-free run 1 cm nearer the road's edge, all else alike
        SignedEdits.editRunsRow(copy, faultFree + 1, line -> {
            String[] cells = line.split(",", -1);
            cells[rho] = String.format(java.util.Locale.ROOT, "%.4f", Double.parseDouble(cells[rho]) - 0.01);
            return String.join(",", cells);
        });
        CliRunner r = CliRunner.run("replay", copy.toString(), "--row", Integer.toString(row), "--png",
                dir.resolve("x.png").toString());
        assertEquals(ExitCode.FAILURE, r.exitCode(), r.out());
        assertTrue(r.err().contains("row " + row + " does not replay: the fault-free run was recorded as")
                && r.err().contains("with other near misses or robustness (runs.csv's near_* and rho_* columns)"), r.err());
    }
}
