package sitcov.protocol;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * A controller program started as a process, under a watchdog shell: the JDK cannot ask the kernel
 * to kill a child when its parent dies, so {@code sh} starts the program in the background, gives
 * it sitcov's stdin, stdout and stderr, lets go of them itself, and once a second checks that
 * sitcov's process is still there; when it is gone (even after {@code kill -9}) the shell kills the
 * program. The program's stderr is copied to a log by a thread of its own, so a chatty controller
 * never blocks, and its last lines are kept for error messages.
 */
final class ControllerProcess {
    /** The stderr tail an error message carries. */
    static final int TAIL_CHARS = 600;
    /** How long a program whose input was closed is given to exit before it is killed. */
    static final long EXIT_MILLIS = 2000;
    /** How long a dead program's stderr is given to be copied to the end, for the error message. */
    static final long DRAIN_MILLIS = 5000;
    /** How long the end of a program's stdout is given to be followed by its exit, for the exit code. */
    static final long EXIT_STATUS_MILLIS = 1000;
    /** A log file keeps this much of its controllers' stderr; the rest is cut (experiments/controllers/README.md, "Timeouts, failures and processes"). */
    static final long LOG_CAP_BYTES = 1 << 20;
    /** Where a log is cut. */
    static final String LOG_CUT = "\n[sitcov: stderr cut at 1 MB; the rest of this log's controller stderr is not kept]\n";
    /** Bytes each log file may still take, by its absolute path: its processes, one after another, share the cap. */
    private static final java.util.Map<Path, java.util.concurrent.atomic.AtomicLong> LOG_ROOM =
            new java.util.concurrent.ConcurrentHashMap<>();

    // $1 is sitcov's pid, the rest is the controller's command line. The background job gets the
    // shell's stdin through fd 3 (a non-interactive shell would give it /dev/null), in a process
    // group of its own where setsid exists, so that whatever it starts is killed with it; the shell
    // then closes its own stdin, stdout and stderr. A watcher in the background checks once a second
    // that sitcov is still there and kills the group when it is gone (even after kill -9); the shell
    // itself waits for the program, and the moment it exits, however, kills its group (so that no
    // descendant keeps the pipes open and sitcov reads the end of its stdout at once), stops the
    // watcher and exits with the program's exit status: the shell's exit is the program's.
    private static final String WATCHDOG = String.join("\n",
            "sitcov=$1; shift",
            "exec 3<&0",
            "if command -v setsid >/dev/null 2>&1; then setsid \"$@\" <&3 3<&- & else \"$@\" <&3 3<&- & fi",
            "child=$!",
            "exec 3<&- </dev/null >/dev/null 2>&1",
            "( while kill -0 \"$sitcov\" 2>/dev/null; do sleep 1; done",
            "  kill -TERM -\"$child\" 2>/dev/null || kill -TERM \"$child\" 2>/dev/null",
            "  sleep 1",
            "  kill -KILL -\"$child\" 2>/dev/null || kill -KILL \"$child\" 2>/dev/null ) &",
            "watcher=$!",
            "wait \"$child\"",
            "code=$?",
            "kill -KILL -\"$child\" 2>/dev/null",
            "kill -KILL \"$watcher\" 2>/dev/null",
            "exit \"$code\"");

    private final Process process;
    private final Thread drain;
    private final StringBuilder tail = new StringBuilder();

    private ControllerProcess(Process process, Path log) throws IOException {
        this.process = process;
        OutputStream logStream = log == null ? OutputStream.nullOutputStream()
                : Files.newOutputStream(log, StandardOpenOption.CREATE, StandardOpenOption.APPEND);
        java.util.concurrent.atomic.AtomicLong room = log == null ? new java.util.concurrent.atomic.AtomicLong(Long.MAX_VALUE)
                : LOG_ROOM.computeIfAbsent(log.toAbsolutePath().normalize(), p -> new java.util.concurrent.atomic.AtomicLong(
                        LOG_CAP_BYTES - sizeOf(p)));
        InputStream err = process.getErrorStream();
        this.drain = new Thread(() -> copy(err, logStream, room), "sitcov-controller-stderr-" + process.pid());
        drain.setDaemon(true);
        drain.start();
    }

    /**
     * Starts {@code command} and handshakes; its stderr is appended to {@code log} (none when null).
     *
     * @throws ControllerStartException naming the command when it cannot be started or fails the handshake
     */
    static Session start(List<String> command, Path log, String sitcovVersion, long handshakeMillis)
            throws ControllerStartException {
        String shown = shown(command);
        List<String> wrapped = new ArrayList<>(List.of("sh", "-c", WATCHDOG, "sitcov-controller",
                Long.toString(ProcessHandle.current().pid())));
        wrapped.addAll(command);
        ControllerProcess started;
        try {
            started = new ControllerProcess(new ProcessBuilder(wrapped).start(), log);
        } catch (IOException e) {
            throw new ControllerStartException("controller " + shown + " could not be started: " + e.getMessage()
                    + (log == null ? "" : " (log " + log + ")"));
        }
        Session session = new Session(shown, new Lines(started.process.getInputStream(), started.process.getOutputStream()),
                started::kill, started::reap, started::tail, started::exitStatus);
        session.handshake(sitcovVersion, handshakeMillis);
        return session;
    }

    /** The command as messages show it: {@code `python3 x.py`}. */
    static String shown(List<String> command) {
        return "`" + String.join(" ", command) + "`";
    }

    /**
     * Kills the program and everything it started, by signal only: the watchdog shell, waiting for
     * the program, then kills its process group (descendants that were orphaned included) and exits.
     * {@link Process#destroyForcibly} of the shell itself would leave the group behind, and would
     * also close the streams, losing the stderr not yet copied to the error message (the JDK closes
     * them itself once the shell has exited). Should the shell not have exited {@link #EXIT_MILLIS}
     * later, it is killed too.
     */
    private void kill() {
        process.descendants().forEach(ProcessHandle::destroyForcibly);
        java.util.concurrent.CompletableFuture.delayedExecutor(EXIT_MILLIS, TimeUnit.MILLISECONDS).execute(() -> {
            if (process.isAlive()) {
                process.descendants().forEach(ProcessHandle::destroyForcibly);
                process.toHandle().destroyForcibly();
            }
        });
    }

    /**
     * How the program ended, for a message about its output's end: " with exit code N" (and the
     * signal that killed it), waiting up to {@link #EXIT_STATUS_MILLIS} for the watchdog shell to
     * pass the exit on; "" when it has not exited (it only closed its stdout).
     */
    private String exitStatus() {
        try {
            process.waitFor(EXIT_STATUS_MILLIS, TimeUnit.MILLISECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        if (process.isAlive()) {
            return "";
        }
        int code = process.exitValue();
        return " with exit code " + code + (code > 128 && code < 128 + 65 ? " (killed by signal " + (code - 128) + ")" : "");
    }

    private static long sizeOf(Path log) {
        try {
            return Files.exists(log) ? Files.size(log) : 0;
        } catch (IOException e) {
            return 0;
        }
    }

    /** Copies stderr to the log while the log has room, marks the cut once, and keeps the tail either way. */
    private void copy(InputStream err, OutputStream log, java.util.concurrent.atomic.AtomicLong room) {
        byte[] buffer = new byte[8192];
        try (log; err) {
            for (int n = err.read(buffer); n >= 0; n = err.read(buffer)) {
                long before = room.getAndAdd(-n);
                if (before > 0) {
                    log.write(buffer, 0, (int) Math.min(n, before));
                }
                if (before >= 0 && before < n) {
                    // the first bytes that do not fit: the room goes below 0 for good
                    log.write(LOG_CUT.getBytes(StandardCharsets.UTF_8));
                }
                if (before >= 0) {
                    log.flush();
                }
                synchronized (tail) {
                    tail.append(new String(buffer, 0, n, StandardCharsets.UTF_8));
                    if (tail.length() > 4 * TAIL_CHARS) {
                        tail.delete(0, tail.length() - TAIL_CHARS);
                    }
                }
            }
        } catch (IOException e) {
            // the program is gone; what it wrote is in the log
        }
    }

    /**
     * The last of its stderr, on one line. Called once the program is dead or killed: waits for the
     * copy to reach the end of its stderr (a loaded machine may take a while to schedule it).
     */
    private String tail() {
        try {
            drain.join(DRAIN_MILLIS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        synchronized (tail) {
            String text = tail.toString().strip();
            if (text.length() > TAIL_CHARS) {
                text = "..." + text.substring(text.length() - TAIL_CHARS);
            }
            return text.replace("\r", "").replace('\n', '|');
        }
    }

    /**
     * After its input was closed: waits up to {@link #EXIT_MILLIS} for the program to exit (the
     * watchdog shell then kills its group and exits), then kills it if it is still there, and
     * returns once the shell is gone and the program's stderr has ended (up to {@link
     * #DRAIN_MILLIS}): by then everything of it that held its stderr has let go of its files.
     */
    private void reap() {
        try {
            if (!process.waitFor(EXIT_MILLIS, TimeUnit.MILLISECONDS)) {
                kill();
                if (!process.waitFor(EXIT_MILLIS, TimeUnit.MILLISECONDS)) {
                    process.descendants().forEach(ProcessHandle::destroyForcibly);
                    process.toHandle().destroyForcibly();
                }
            }
            drain.join(DRAIN_MILLIS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            kill();
        }
    }
}
