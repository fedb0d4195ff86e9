package sitcov.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Set;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import sitcov.judge.LiveRun;
import sitcov.oracle.Outcome;
import sitcov.world.Situations;
import sitcov.world.WorldMap;

/**
 * A controller's whole process group goes with it: a controller that forks a child which keeps its
 * pipes open and then exits is a CONTROLLER_ERROR naming its exit code at once (not a timeout once
 * the child lets go), and the child is gone; a child forked by a well-behaved controller is gone once
 * the controllers are closed; a chatty controller's stderr log is cut at its cap, and the cut is
 * marked. The children sleep for minutes; nothing here waits for them.
 */
class ControllerProcessTest {
    private static final WorldMap STRAIGHT = Situations.withoutTraffic(Situations.straight(List.of()));

    /** $1: the mode, $2: where the background child's pid is written. */
    private static final String SCRIPT = String.join("\n",
            "read hello",
            "echo '{\"type\":\"hello\",\"protocol\":1,\"name\":\"test\",\"version\":\"1\"}'",
            "if [ \"$1\" = fork-early ]; then sleep 300 & echo $! > \"$2\"; fi",
            "n=0",
            "while read line; do",
            "  case \"$line\" in",
            "    *'\"type\":\"observation\"'*)",
            "      n=$((n+1))",
            "      if [ \"$1\" = fork-exit ] && [ $n -ge 3 ]; then",
            "        sleep 300 & echo $! > \"$2\"",
            "        echo \"leaving my child behind\" >&2",
            "        exit 4",
            "      fi",
            "      echo '{\"type\":\"command\",\"speed_change\":0.1,\"steering\":0}' ;;",
            "  esac",
            "done",
            "");

    @TempDir
    Path dir;

    @Test
    void aControllerThatExitsLeavingAChildOnItsPipesIsAControllerErrorWithItsExitCodeAndTheChildIsGone()
            throws IOException {
        Path pidFile = dir.resolve("child.pid");
        // a tick timeout far above the time the exit takes to be seen: a blocked read would end in CONTROLLER_TIMEOUT
        try (ExecControllers controllers = new ExecControllers(command("fork-exit", pidFile), "test", 30_000, 10_000)) {
            LiveRun run = runToEnd(controllers.worker(null));
            assertEquals(Outcome.CONTROLLER_ERROR, run.record().result().outcome());
            String failure = run.scene().autonomousCar().failure().getMessage();
            assertTrue(failure.contains("it exited with exit code 4 at tick 2"), failure);
            assertTrue(failure.contains("its stderr ends: leaving my child behind"), failure);
            assertGone(pidFile);
        }
    }

    @Test
    void aChildOfAControllerIsGoneOnceTheControllersAreClosed() throws IOException {
        Path pidFile = dir.resolve("child.pid");
        try (ExecControllers controllers = new ExecControllers(command("fork-early", pidFile), "test")) {
            LiveRun run = runToEnd(controllers.worker(null));
            assertEquals(Outcome.TARGET_REACHED, run.record().result().outcome());
            assertTrue(isRunning(pid(pidFile)), "the child runs while its controller does");
        }
        assertGone(pidFile);
    }

    @Test
    void aControllersStderrLogIsCutAtItsCapAndTheCutIsMarked() throws IOException, ControllerStartException {
        Path script = Files.writeString(dir.resolve("chatty.sh"), String.join("\n",
                "head -c 1500000 /dev/zero | tr '\\0' x >&2",
                "read hello",
                "echo '{\"type\":\"hello\",\"protocol\":1}'",
                "while read line; do :; done",
                ""));
        Path log = dir.resolve("controller-0.log");
        ExecControllers controllers = new ExecControllers(List.of("sh", script.toString()), "test");
        controllers.check(log);
        byte[] marker = ControllerProcess.LOG_CUT.getBytes(StandardCharsets.UTF_8);
        assertEquals(ControllerProcess.LOG_CAP_BYTES + marker.length, Files.size(log));
        assertTrue(Files.readString(log).endsWith("x" + ControllerProcess.LOG_CUT));
        // a later process of the same log adds nothing: the cap is the log's
        controllers.check(log);
        assertEquals(ControllerProcess.LOG_CAP_BYTES + marker.length, Files.size(log));
    }

    private List<String> command(String mode, Path pidFile) throws IOException {
        Path script = Files.writeString(dir.resolve("controller.sh"), SCRIPT);
        return List.of("sh", script.toString(), mode, pidFile.toString());
    }

    private static long pid(Path pidFile) throws IOException {
        return Long.parseLong(Files.readString(pidFile).strip());
    }

    private static void assertGone(Path pidFile) throws IOException {
        long pid = pid(pidFile);
        assertTrue(!isRunning(pid), "the controller's child " + pid + " is still running");
    }

    /**
     * Whether {@code pid} runs and holds files. A killed child is gone, a zombie its parent (an init
     * that may not reap) has not collected, or one past letting go of its files: sitcov saw its
     * controller's output end, or its stderr, only after that.
     */
    private static boolean isRunning(long pid) throws IOException {
        Path proc = Path.of("/proc", Long.toString(pid));
        if (!Files.isDirectory(Path.of("/proc/self"))) {
            return ProcessHandle.of(pid).map(ProcessHandle::isAlive).orElse(false);
        }
        if (!Files.exists(proc)) {
            return false;
        }
        try {
            String stat = Files.readString(proc.resolve("stat"));
            char state = stat.substring(stat.lastIndexOf(')') + 2).charAt(0);
            if (state == 'Z' || state == 'X') {
                return false;
            }
            try (Stream<Path> files = Files.list(proc.resolve("fd"))) {
                return files.findAny().isPresent();
            }
        } catch (IOException e) {
            // it went while we looked
            return false;
        }
    }

    private static LiveRun runToEnd(sitcov.control.ControllerFactory controllers) {
        LiveRun run = new LiveRun(STRAIGHT, 1, Set.of(), controllers);
        while (run.step()) {
            // to the end
        }
        return run;
    }
}
