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
    void theBuiltinAnswersSitcovsOfferWithProtocol2UnlessToldToSpeakProtocol1() throws UsageException {
        String offer = "{\"type\":\"hello\",\"protocol\":2,\"protocols\":[1,2],\"sitcov\":\"test\"}\n"
                + "{\"type\":\"reset\",\"map\":{\"seed\":1,\"roads\":[{\"id\":0,\"axis\":\"east_west\",\"centre\":0,"
                + "\"from\":0,\"to\":100}],\"junctions\":[],\"target\":{\"x\":90,\"y\":-1.5,\"road\":0},"
                + "\"start\":{\"x\":10,\"y\":-1.5,\"heading\":90}},\"internal_seed\":1,\"faults\":[]}\n"
                + "{\"type\":\"observation\",\"tick\":0,\"x\":10,\"y\":-1.5,\"heading\":90,\"speed\":0,"
                + "\"traffic\":[],\"obstacles\":[],\"junctions\":[]}\n";
        for (String protocol : List.of("2", "1")) {
            ByteArrayOutputStream out = new ByteArrayOutputStream();
            ByteArrayOutputStream err = new ByteArrayOutputStream();
            ControllerCommand command = new ControllerCommand(new ByteArrayInputStream(offer.getBytes(StandardCharsets.UTF_8)),
                    out);
            int code = command.run(List.of("builtin", "--protocol", protocol), null,
                    new PrintStream(err, true, StandardCharsets.UTF_8));
            assertEquals(ExitCode.OK, code, err.toString(StandardCharsets.UTF_8));
            String[] answers = out.toString(StandardCharsets.UTF_8).split("\n");
            assertTrue(answers[0].startsWith("{\"type\":\"hello\",\"protocol\":" + protocol + ","), answers[0]);
            String tick = protocol.equals("2") ? "\"tick\":0," : "";
            assertTrue(answers[1].startsWith("{\"type\":\"command\"," + tick + "\"speed"), answers[1]);
        }
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
