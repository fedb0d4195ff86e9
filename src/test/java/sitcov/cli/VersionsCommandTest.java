package sitcov.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class VersionsCommandTest {
    @Test
    void versionsWritesARowPerMapAndVariantAndAVerdictPerVariant(@TempDir Path dir) throws Exception {
        Path out = dir.resolve("v");
        CliRunner r = CliRunner.run("versions", "--reference", "builtin", "--variants", "builtin:4;builtin:16", "--maps", "3",
                "--threads", "1", "--out", out.toString());
        assertEquals(ExitCode.OK, r.exitCode(), r.err());
        List<String> rows = Files.readAllLines(out.resolve("versions.csv"));
        assertEquals(1 + 3 * 2, rows.size(), "a header and one row per map and variant");
        assertTrue(rows.get(1).startsWith("1,1,1,"), rows.get(1));
        String verdict = Files.readString(out.resolve("verdict.txt"));
        assertTrue(verdict.contains("variant 1: builtin:4") && verdict.contains("variant 2: builtin:16"), verdict);
        // fault 4 (a steering fault) leaves the road on almost every map: it must regress somewhere in three
        long regressedWith4 = rows.stream().skip(1).filter(l -> l.split(",", -1)[2].equals("1"))
                .filter(l -> !l.split(",", -1)[9].isEmpty()).count();
        assertTrue(regressedWith4 > 0, String.join("\n", rows));
        assertTrue(verdict.contains("fails where the reference did not: " + regressedWith4 + " of 3 maps"), verdict);
    }

    @Test
    void aControllerThatFailsItsHandshakeStopsVersionsBeforeAnyFolderIsMade(@TempDir Path dir) {
        Path out = dir.resolve("never");
        CliRunner r = CliRunner.run("versions", "--reference", "exec:sh -c 'exit 3'", "--variants", "builtin",
                "--maps", "2", "--out", out.toString());
        assertEquals(ExitCode.USAGE, r.exitCode(), r.err());
        assertTrue(r.err().contains("failed the handshake"), r.err());
        assertTrue(!Files.exists(out), "nothing is written for a controller that cannot start");
    }

    @Test
    void aPresetThatDoesNotExistIsNamedWithTheShippedOne() {
        CliRunner r = CliRunner.run("versions", "nosuch");
        assertEquals(ExitCode.USAGE, r.exitCode());
        assertTrue(r.err().contains("versions: no preset 'nosuch'") && r.err().contains("byo-controller"), r.err());
    }

    @Test
    void aVariantThatNamesNoControllerIsRefusedWithTheFix() {
        CliRunner r = CliRunner.run("versions", "--reference", "builtin", "--variants", "builtin:99", "--maps", "2");
        assertEquals(ExitCode.USAGE, r.exitCode());
        assertTrue(r.err().contains("'99' is not a fault") && r.err().contains("ids 0-19"), r.err());
    }
}
