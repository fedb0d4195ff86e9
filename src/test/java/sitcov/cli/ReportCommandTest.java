package sitcov.cli;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import sitcov.results.ResultsFolder;

class ReportCommandTest {
    @Test
    void aFolderWhoseStatisticsWereLostGetsTheSameOnesBackFromItsJournal(@TempDir Path dir) throws Exception {
        Path copy = dir.resolve("copy");
        ResultsFolders.copy(ResultsFolders.tinyReference(), copy);
        Files.delete(copy.resolve(ResultsFolder.STATS));
        Files.delete(copy.resolve(ResultsFolder.VERDICT));
        Files.writeString(copy.resolve(ResultsFolder.SUMMARY), "stale\n");
        CliRunner r = CliRunner.run("report", copy.toString());
        assertEquals(0, r.exitCode(), r.err());
        ResultsFolders.assertSameResults(ResultsFolders.tinyReference(), copy);
        assertTrue(r.out().contains("Verdict (kept in "), r.out());
    }

    @Test
    void aFolderThatIsNotCompleteIsSentToResume(@TempDir Path dir) throws Exception {
        Path copy = dir.resolve("unfinished");
        Files.createDirectories(copy);
        Path manifest = ResultsFolders.tinyReference().resolve(ResultsFolder.MANIFEST);
        Files.writeString(copy.resolve(ResultsFolder.MANIFEST), Files.readString(manifest).replace("complete=true", "complete=false"));
        Files.copy(ResultsFolders.tinyReference().resolve(ResultsFolder.GRID), copy.resolve(ResultsFolder.GRID));
        CliRunner r = CliRunner.run("report", copy.toString());
        assertEquals(2, r.exitCode());
        assertTrue(r.err().contains("run --resume"), r.err());
        assertFalse(Files.exists(copy.resolve(ResultsFolder.STATS)), "nothing written");
    }

    /** A copy of the tiny reference with {@code from} replaced by {@code to} once in {@code file}. */
    private static Path edited(Path dir, String name, String file, String from, String to) throws Exception {
        Path copy = dir.resolve(name);
        ResultsFolders.copy(ResultsFolders.tinyReference(), copy);
        String text = Files.readString(copy.resolve(file));
        assertTrue(text.contains(from), file + " holds " + from);
        Files.writeString(copy.resolve(file), text.replaceFirst(java.util.regex.Pattern.quote(from),
                java.util.regex.Matcher.quoteReplacement(to)));
        return copy;
    }

    @Test
    void aFolderEditedByHandIsRefusedNamingWhatChanged(@TempDir Path dir) throws Exception {
        List<String> runs = Files.readAllLines(ResultsFolders.tinyReference().resolve(ResultsFolder.RUNS));
        int found = 0;
        while (!runs.get(found).contains(",FOUND,")) {
            found++;
        }
        String foundRow = runs.get(found);
        String faultFree = runs.get(1);
        String[] cells = faultFree.split(",", -1);
        cells[13] = Long.toString(Long.parseLong(cells[13]) + 1); // its ticks, one more
        List<String[]> edits = List.of(
                new String[] {ResultsFolder.RUNS, foundRow, foundRow.replace(",FOUND,", ",EFFECT_NO_FAILURE,"),
                        "runs.csv:" + (found + 1) + ": this row was changed after sitcov wrote it"},
                new String[] {ResultsFolder.RUNS, faultFree, String.join(",", cells),
                        "runs.csv:2: this row was changed after sitcov wrote it"},
                new String[] {ResultsFolder.DRIVERS, "\n0,random,", "\n0,random,1", "drivers.csv:3: this row was changed"},
                new String[] {ResultsFolder.MANIFEST, "\nmaster_seed=7\n", "\nmaster_seed=8\n",
                        "manifest.properties: master_seed was changed after sitcov wrote it"},
                new String[] {ResultsFolder.MANIFEST, "\nreplications=3\n", "\nreplications=2\n",
                        "manifest.properties: replications was changed"},
                new String[] {ResultsFolder.MANIFEST, "\ndrivers=coverage-filter,random\n", "\ndrivers=random,coverage-filter\n",
                        "manifest.properties: drivers was changed"});
        for (int i = 0; i < edits.size(); i++) {
            String[] e = edits.get(i);
            Path copy = edited(dir, "edit-" + i, e[0], e[1], e[2]);
            byte[] summary = Files.readAllBytes(copy.resolve(ResultsFolder.SUMMARY));
            CliRunner r = CliRunner.run("report", copy.toString());
            assertEquals(ExitCode.USAGE, r.exitCode(), e[3] + ": " + r.out());
            assertTrue(r.err().contains(copy.resolve(e[3].substring(0, e[3].indexOf(':'))) + e[3].substring(e[3].indexOf(':'))),
                    r.err());
            assertTrue(r.err().contains("or run the experiment again into a new folder"), r.err());
            assertArrayEquals(summary, Files.readAllBytes(copy.resolve(ResultsFolder.SUMMARY)), "nothing written again");
        }
    }

    @Test
    void theTemporaryFilesAKilledWriteLeftAreSweptButNoOtherFile(@TempDir Path dir) throws Exception {
        Path copy = dir.resolve("copy");
        ResultsFolders.copy(ResultsFolders.tinyReference(), copy);
        Path stale = copy.resolve(".summary.csv4711.tmp");
        Path picture = copy.resolve("replays").resolve(".fault-14.png42.tmp");
        Path forest = copy.resolve("." + ResultsFolder.forestPlot(1, "coverage-filter", "random") + "77.tmp");
        Path mine = copy.resolve(".notes.tmp");
        for (Path p : List.of(stale, picture, forest, mine)) {
            Files.writeString(p, "half");
        }
        CliRunner r = CliRunner.run("report", copy.toString());
        assertEquals(0, r.exitCode(), r.err());
        assertFalse(Files.exists(stale) || Files.exists(picture) || Files.exists(forest),
                "sitcov's own temporary files are swept");
        assertEquals("half", Files.readString(mine), "a file sitcov does not name is kept");
        Files.delete(mine);
        ResultsFolders.assertSameResults(ResultsFolders.tinyReference(), copy);
    }

    /** {@code file}'s lines without their last {@code columns} columns. */
    private static void dropColumns(Path file, int columns) throws Exception {
        List<String> lines = new java.util.ArrayList<>();
        for (String line : Files.readAllLines(file)) {
            for (int c = 0; c < columns; c++) {
                line = line.substring(0, line.lastIndexOf(','));
            }
            lines.add(line);
        }
        Files.write(file, lines);
    }

    @Test
    void aFolderWrittenBeforeChecksIsReportedAsItIsWithAWarning(@TempDir Path dir) throws Exception {
        Path older = dir.resolve("older");
        ResultsFolders.copy(ResultsFolders.tinyReference(), older);
        Path manifest = older.resolve(ResultsFolder.MANIFEST);
        Files.writeString(manifest, Files.readString(manifest).replaceAll("(?m)^checks=.*\n", ""));
        dropColumns(older.resolve(ResultsFolder.RUNS), 2);
        dropColumns(older.resolve(ResultsFolder.DRIVERS), 1);
        dropColumns(older.resolve(ResultsFolder.TIMINGS), 1);
        assertTrue(Files.readAllLines(older.resolve(ResultsFolder.RUNS)).get(0).endsWith(",rho_timeout"));
        Path expected = dir.resolve("expected");
        ResultsFolders.copy(older, expected);
        Files.delete(older.resolve(ResultsFolder.STATS));

        CliRunner r = CliRunner.run("report", older.toString());
        assertEquals(0, r.exitCode(), r.err());
        assertTrue(r.err().contains("warning: " + older + " was written before sitcov checked its results folders"), r.err());
        assertTrue(r.err().contains("for a folder that is checked, run --again " + older + "."), r.err());
        ResultsFolders.assertSameResults(expected, older);
        assertArrayEquals(Files.readAllBytes(expected.resolve(ResultsFolder.TIMINGS)),
                Files.readAllBytes(older.resolve(ResultsFolder.TIMINGS)), "the journal keeps its older form");
    }
}
