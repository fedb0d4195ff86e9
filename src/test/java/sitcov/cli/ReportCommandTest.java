package sitcov.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import sitcov.report.ResultsFolder;

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
}
