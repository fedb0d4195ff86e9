package sitcov.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code controller builtin} speaks the protocol on its streams; {@code simulate --controller} refuses a controller that cannot handshake. */
class ControllerCommandTest {

    @Test
    void theBuiltinAnswersHelloWithItsNameAndProtocol() throws UsageException {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        String hello = "{\"type\":\"hello\",\"protocol\":1,\"sitcov\":\"test\"}\n";
        ControllerCommand command = new ControllerCommand(new ByteArrayInputStream(hello.getBytes(StandardCharsets.UTF_8)), out);
        int code = command.run(List.of("builtin"), null, new PrintStream(err, true, StandardCharsets.UTF_8));
        assertEquals(ExitCode.OK, code, err.toString(StandardCharsets.UTF_8));
        String answer = out.toString(StandardCharsets.UTF_8);
        assertTrue(answer.startsWith("{\"type\":\"hello\",\"protocol\":1,\"name\":\"sitcov-builtin\""), answer);
        assertTrue(answer.endsWith("}\n") && answer.indexOf('\n') == answer.length() - 1, "one line: " + answer);
    }

    @Test
    void aControllerOtherThanBuiltinIsAUsageError() {
        CliRunner result = CliRunner.run("controller", "mine");
        assertEquals(ExitCode.USAGE, result.exitCode());
        assertTrue(result.err().contains("'controller builtin'"), result.err());
    }

    @Test
    void simulateWithAControllerThatFailsTheHandshakeStopsWithExitTwoNamingTheCommand(@TempDir Path dir)
            throws IOException {
        Path script = Files.writeString(dir.resolve("mute.sh"), "read hello\necho 'hello yourself'\n");
        CliRunner result = CliRunner.run("simulate", "--seed", "3", "--controller", "exec:sh " + script);
        assertEquals(ExitCode.USAGE, result.exitCode());
        assertEquals("", result.out());
        assertTrue(result.err().startsWith("sitcov: simulate: controller `sh " + script + "` failed the handshake: not JSON"),
                result.err());
    }

    @Test
    void aRunWhoseControllerFailsPrintsItsOutcomeAndSaysWhy(@TempDir Path dir) throws IOException {
        Path script = Files.writeString(dir.resolve("garbage.sh"),
                "read hello\necho '{\"type\":\"hello\",\"protocol\":1}'\nread reset\nread tick0\necho garbage\nread rest\n");
        CliRunner result = CliRunner.run("simulate", "--seed", "3", "--controller", "exec:sh " + script);
        assertEquals(ExitCode.OK, result.exitCode(), result.err());
        assertTrue(result.out().startsWith("seed 3 internal 3: CONTROLLER_ERROR after 1 ticks"), result.out());
        assertTrue(result.err().contains("simulate: controller `sh " + script + "`: at tick 0 it wrote 'garbage': not JSON"),
                result.err());
    }

    @Test
    void simulateWithAControllerThatIsNeitherBuiltinNorExecIsAUsageError() {
        CliRunner result = CliRunner.run("simulate", "--seed", "3", "--controller", "python3 x.py");
        assertEquals(ExitCode.USAGE, result.exitCode());
        assertTrue(result.err().contains("a controller is builtin, builtin:FAULTS"), result.err());
    }
}
