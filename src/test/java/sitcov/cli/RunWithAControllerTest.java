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
    void anExperimentOnAnotherControllerKeepsItInTheManifestDrawsNoBuiltinReplaysAndReplaySaysHowToRunIt(@TempDir Path dir)
            throws Exception {
        Path out = dir.resolve("planted");
        CliRunner r = CliRunner.run("run", ResultsFolders.TINY, "--replications", "1", "--out", out.toString(),
                "--controller", "builtin:16", "--threads", "1");
        assertEquals(ExitCode.OK, r.exitCode(), r.err());
        assertTrue(Files.readString(out.resolve("manifest.properties")).contains("controller=builtin:16\n"));
        assertFalse(Files.exists(out.resolve("replays")) && Files.list(out.resolve("replays")).findAny().isPresent(),
                "replay pictures run the builtin car, so a folder of another controller has none");
        String report = Files.readString(out.resolve("report.html"));
        assertTrue(report.contains("<span>simulate</span>") && report.contains("<span>&quot;builtin:16&quot;</span>")
                && !report.contains("<span>replay</span>"), "the report's commands run the folder's controller");
        CliRunner replay = CliRunner.run("replay", out.toString(), "--row", "1");
        assertEquals(ExitCode.USAGE, replay.exitCode());
        assertTrue(replay.err().contains("--controller \"builtin:16\"") && replay.err().contains("simulate --seed "),
                replay.err());
    }

    @Test
    void aControllerThatNamesNothingIsRefusedWithWhatIsAccepted(@TempDir Path dir) {
        CliRunner r = CliRunner.run("run", "smoke", "--out", dir.resolve("x").toString(), "--controller", "python3 me.py");
        assertEquals(ExitCode.USAGE, r.exitCode());
        assertTrue(r.err().contains("builtin:FAULTS") && r.err().contains("exec:COMMAND"), r.err());
    }
}
