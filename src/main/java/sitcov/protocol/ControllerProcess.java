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

    // $1 is sitcov's pid, the rest is the controller's command line. The background job gets the
    // shell's stdin through fd 3 (a non-interactive shell would give it /dev/null), in a process
    // group of its own where setsid exists, so that whatever it starts is killed with it; the shell
    // then closes its own stdin, stdout and stderr, so the program's exit is seen at once as the end
    // of its stdout.
    private static final String WATCHDOG = String.join("\n",
            "sitcov=$1; shift",
            "exec 3<&0",
            "if command -v setsid >/dev/null 2>&1; then setsid \"$@\" <&3 3<&- & else \"$@\" <&3 3<&- & fi",
            "child=$!",
            "exec 3<&- </dev/null >/dev/null 2>&1",
            "while kill -0 \"$sitcov\" 2>/dev/null; do sleep 1; done",
            "kill -TERM -\"$child\" 2>/dev/null || kill -TERM \"$child\" 2>/dev/null",
            "sleep 1",
            "kill -KILL -\"$child\" 2>/dev/null || kill -KILL \"$child\" 2>/dev/null");

    private final Process process;
    private final Thread drain;
    private final StringBuilder tail = new StringBuilder();

    private ControllerProcess(Process process, Path log) throws IOException {
        this.process = process;
        OutputStream logStream = log == null ? OutputStream.nullOutputStream()
                : Files.newOutputStream(log, StandardOpenOption.CREATE, StandardOpenOption.APPEND);
        InputStream err = process.getErrorStream();
        this.drain = new Thread(() -> copy(err, logStream), "sitcov-controller-stderr-" + process.pid());
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
                started::kill, started::reap, started::tail);
        session.handshake(sitcovVersion, handshakeMillis);
        return session;
    }

    /** The command as messages show it: {@code `python3 x.py`}. */
    static String shown(List<String> command) {
        return "`" + String.join(" ", command) + "`";
    }

    /**
     * Kills the program, everything it started, and the watchdog shell, by signal only:
     * {@link Process#destroyForcibly} would also close the streams, and the stderr not yet copied
     * would be lost to the error message (the JDK closes them itself once the shell has exited).
     */
    private void kill() {
        process.descendants().forEach(ProcessHandle::destroyForcibly);
        process.toHandle().destroyForcibly();
    }

    private void copy(InputStream err, OutputStream log) {
        byte[] buffer = new byte[8192];
        try (log; err) {
            for (int n = err.read(buffer); n >= 0; n = err.read(buffer)) {
                log.write(buffer, 0, n);
                log.flush();
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
     * After its input was closed: waits up to {@link #EXIT_MILLIS} for the program to exit, then
     * kills it (if it is still there) and the watchdog shell, which would otherwise go on watching.
     */
    private void reap() {
        // the watchdog's own `sleep 1` is no program to wait for
        List<ProcessHandle> programs = process.descendants()
                .filter(p -> !p.info().command().map(c -> c.endsWith("/sleep") || c.equals("sleep")).orElse(false))
                .toList();
        long until = System.nanoTime() + EXIT_MILLIS * 1_000_000;
        try {
            for (ProcessHandle p : programs) {
                long left = until - System.nanoTime();
                if (left > 0) {
                    p.onExit().get(left, TimeUnit.NANOSECONDS);
                }
            }
        } catch (java.util.concurrent.ExecutionException | java.util.concurrent.TimeoutException e) {
            // killed below
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        kill();
    }
}
