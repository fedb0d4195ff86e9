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
    void aControllerThatNamesNothingIsRefusedWithWhatIsAccepted(@TempDir Path dir) {
        CliRunner r = CliRunner.run("run", "smoke", "--out", dir.resolve("x").toString(), "--controller", "python3 me.py");
        assertEquals(ExitCode.USAGE, r.exitCode());
        assertTrue(r.err().contains("builtin:FAULTS") && r.err().contains("exec:COMMAND"), r.err());
    }
}
