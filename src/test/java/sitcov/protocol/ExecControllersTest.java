package sitcov.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import sitcov.control.ControllerFactory;
import sitcov.judge.LiveRun;
import sitcov.oracle.Outcome;
import sitcov.world.Situations;
import sitcov.world.WorldMap;

/**
 * Misbehaving controllers never hang or break a run: a controller that sleeps past the per-tick
 * timeout, exits mid-run or writes garbage ends its run with its outcome and the reason, and the
 * next run gets a fresh process that works; one that fails the handshake is refused with a message
 * naming its command. The controllers are small shell scripts speaking the deprecated protocol 1
 * (still accepted; protocol 2's tick echo is tested in {@link TickEchoTest}): the first process of each
 * misbehaves at its third observation, the ones after it (a marker file tells them apart) answer
 * every observation with full throttle straight on, which takes the car to the Target on the
 * straight road.
 */
class ExecControllersTest {
    private static final WorldMap STRAIGHT = Situations.withoutTraffic(Situations.straight(List.of()));

    private static final String SCRIPT = String.join("\n",
            "read hello",
            "echo '{\"type\":\"hello\",\"protocol\":1,\"name\":\"test\",\"version\":\"1\"}'",
            "first=no",
            "if [ ! -e \"$2\" ]; then : > \"$2\"; first=yes; fi",
            "n=0",
            "while read line; do",
            "  case \"$line\" in",
            "    *'\"type\":\"observation\"'*)",
            "      n=$((n+1))",
            "      if [ $first = yes ] && [ $n -ge 3 ]; then",
            "        case $1 in",
            "          sleep) sleep 30 ;;",
            "          exit) echo \"giving up at observation $n\" >&2; exit 3 ;;",
            "          garbage) echo \"about to write garbage\" >&2; echo 'this is not JSON'; continue ;;",
            "          malformed) echo '{\"type\":\"command\",\"speed_change\":\"fast\",\"steering\":0}'; continue ;;",
            "        esac",
            "      fi",
            "      echo '{\"type\":\"command\",\"speed_change\":0.1,\"steering\":0}' ;;",
            "  esac",
            "done",
            "");

    @TempDir
    Path dir;

    @Test
    void aControllerThatSleepsPastTheTimeoutEndsItsRunWithControllerTimeoutAndTheNextRunWorks() throws IOException {
        Runs runs = twoRuns("sleep", 300);
        assertEquals(Outcome.CONTROLLER_TIMEOUT, runs.first.record().result().outcome());
        assertTrue(runs.firstFailure.contains("within 300 ms at tick 2"), runs.firstFailure);
        assertEquals(Outcome.TARGET_REACHED, runs.second.record().result().outcome());
    }

    @Test
    void aControllerThatExitsMidRunEndsItWithControllerErrorAndItsStderrAndTheNextRunWorks() throws IOException {
        Runs runs = twoRuns("exit", 5000);
        assertEquals(Outcome.CONTROLLER_ERROR, runs.first.record().result().outcome());
        assertTrue(runs.firstFailure.contains("exited with exit code 3 at tick 2"), runs.firstFailure);
        assertTrue(runs.firstFailure.contains("its stderr ends: giving up at observation 3"), runs.firstFailure);
        assertEquals(Outcome.TARGET_REACHED, runs.second.record().result().outcome());
    }

    @Test
    void aControllerThatWritesGarbageEndsItsRunWithControllerErrorAndTheNextRunWorks() throws IOException {
        Runs runs = twoRuns("garbage", 5000);
        assertEquals(Outcome.CONTROLLER_ERROR, runs.first.record().result().outcome());
        assertTrue(runs.firstFailure.contains("'this is not JSON'"), runs.firstFailure);
        assertTrue(runs.firstFailure.contains("about to write garbage"), runs.firstFailure);
        assertEquals(Outcome.TARGET_REACHED, runs.second.record().result().outcome());
    }

    @Test
    void aCommandWithAMalformedMemberIsAControllerErrorNamingTheMember() throws IOException {
        Runs runs = twoRuns("malformed", 5000);
        assertEquals(Outcome.CONTROLLER_ERROR, runs.first.record().result().outcome());
        assertTrue(runs.firstFailure.contains("command.speed_change must be a number"), runs.firstFailure);
        assertEquals(Outcome.TARGET_REACHED, runs.second.record().result().outcome());
    }

    @Test
    void aControllerOfAnotherProtocolFailsTheHandshakeWithAMessageNamingItsCommand() throws IOException {
        Path script = write("other.sh", "read hello\necho '{\"type\":\"hello\",\"protocol\":3}'\nread rest\n");
        ExecControllers controllers = new ExecControllers(List.of("sh", script.toString()), "test");
        ControllerStartException refused = assertThrows(ControllerStartException.class, () -> controllers.check(null));
        assertEquals("controller `sh " + script + "` failed the handshake: it speaks protocol 3; this sitcov speaks"
                + " protocols 1 and 2", refused.getMessage());
    }

    @Test
    void aControllerThatExitsBeforeItsHelloFailsTheHandshakeWithItsStderr() throws IOException {
        Path script = write("gone.sh", "echo 'cannot load my model' >&2\nexit 1\n");
        ExecControllers controllers = new ExecControllers(List.of("sh", script.toString()), "test");
        ControllerStartException refused = assertThrows(ControllerStartException.class, () -> controllers.check(null));
        assertTrue(refused.getMessage().endsWith("failed the handshake: it exited before its hello; its stderr ends:"
                + " cannot load my model"), refused.getMessage());
    }

    @Test
    void aControllerThatCannotHandshakeMidExperimentEndsTheRunWithControllerError() throws IOException {
        Path script = write("silent.sh", "echo 'not a hello'\n");
        try (ExecControllers controllers = new ExecControllers(List.of("sh", script.toString()), "test")) {
            LiveRun run = runToEnd(controllers.worker(null));
            assertEquals(Outcome.CONTROLLER_ERROR, run.record().result().outcome());
            assertTrue(run.scene().autonomousCar().failure().getMessage().contains("failed the handshake"));
        }
    }

    @Test
    void theControllersStderrGoesToTheLog() throws IOException {
        Path log = dir.resolve("controller-0.log");
        try (ExecControllers controllers = new ExecControllers(List.of("sh", write("c.sh", SCRIPT).toString(), "exit",
                dir.resolve("marker").toString()), "test")) {
            runToEnd(controllers.worker(log));
        }
        assertEquals("giving up at observation 3\n", Files.readString(log));
    }

    private record Runs(LiveRun first, String firstFailure, LiveRun second) {
    }

    /** Two runs on one worker's factory with the script in {@code mode}. */
    private Runs twoRuns(String mode, long tickTimeoutMillis) throws IOException {
        Path script = write("controller.sh", SCRIPT);
        List<String> command = List.of("sh", script.toString(), mode, dir.resolve("marker").toString());
        try (ExecControllers controllers = new ExecControllers(command, "test", tickTimeoutMillis, 10_000)) {
            ControllerFactory worker = controllers.worker(null);
            LiveRun first = runToEnd(worker);
            String failure = first.scene().autonomousCar().failure().getMessage();
            assertTrue(failure.startsWith("controller `sh " + script + " " + mode), failure);
            return new Runs(first, failure, runToEnd(worker));
        }
    }

    private static LiveRun runToEnd(ControllerFactory controllers) {
        LiveRun run = new LiveRun(STRAIGHT, 1, Set.of(), controllers);
        while (run.step()) {
            // to the end
        }
        return run;
    }

    private Path write(String name, String text) throws IOException {
        return Files.writeString(dir.resolve(name), text);
    }
}
