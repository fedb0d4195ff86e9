package sitcov.protocol;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * Controller programs started from one command line, one process per worker thread: each
 * {@link #worker} factory starts its process at its first run, reuses it run after run, and starts
 * a fresh one after a failure. {@link #check} starts one eagerly so that a command that cannot
 * handshake stops sitcov before anything runs (experiments/controllers/README.md, "Testing your own controller").
 */
public final class ExecControllers implements AutoCloseable {
    /** The per-tick timeout unless configured: generous for a slow controller on a loaded machine. */
    public static final long DEFAULT_TICK_TIMEOUT_MILLIS = 5000;
    /** The handshake's timeout unless configured: room for a JVM or a Python interpreter to start. */
    public static final long DEFAULT_HANDSHAKE_TIMEOUT_MILLIS = 20000;

    private final List<String> command;
    private final String sitcovVersion;
    private final long tickTimeoutMillis;
    private final long handshakeTimeoutMillis;
    private final List<ProxyFactory> workers = new ArrayList<>();

    public ExecControllers(List<String> command, String sitcovVersion, long tickTimeoutMillis,
                           long handshakeTimeoutMillis) {
        if (command.isEmpty()) {
            throw new IllegalArgumentException("a controller needs a command");
        }
        this.command = List.copyOf(command);
        this.sitcovVersion = sitcovVersion;
        this.tickTimeoutMillis = tickTimeoutMillis;
        this.handshakeTimeoutMillis = handshakeTimeoutMillis;
    }

    public ExecControllers(List<String> command, String sitcovVersion) {
        this(command, sitcovVersion, DEFAULT_TICK_TIMEOUT_MILLIS, DEFAULT_HANDSHAKE_TIMEOUT_MILLIS);
    }

    /** The command as messages show it, e.g. {@code `python3 x.py`}. */
    public String shown() {
        return ControllerProcess.shown(command);
    }

    /**
     * The controller factory of one worker thread; its process's stderr is appended to {@code log}
     * (e.g. controller-0.log in the results folder; discarded when null). Not thread-safe: one
     * thread uses it. {@link #close} ends its process.
     */
    public synchronized ProxyFactory worker(Path log) {
        ProxyFactory factory = new ProxyFactory(() -> ControllerProcess.start(command, log, sitcovVersion,
                handshakeTimeoutMillis), tickTimeoutMillis);
        workers.add(factory);
        return factory;
    }

    /**
     * One process that steps up to {@code maxBatch} runs together (batched lockstep), started and
     * handshaken now; its stderr is appended to {@code log} (discarded when null). {@link
     * BatchingProxy#close} ends it.
     *
     * @throws ControllerStartException naming the command and what went wrong
     */
    public BatchingProxy batched(Path log, int maxBatch) throws ControllerStartException {
        return BatchingProxy.open(() -> ControllerProcess.start(command, log, sitcovVersion, handshakeTimeoutMillis),
                tickTimeoutMillis, maxBatch);
    }

    /**
     * Starts one process, handshakes, and ends it: the controller's name and version when it
     * answered as the protocol asks.
     *
     * @throws ControllerStartException naming the command and what went wrong
     */
    public String check(Path log) throws ControllerStartException {
        Session session = ControllerProcess.start(command, log, sitcovVersion, handshakeTimeoutMillis);
        Wire.Hello hello = session.hello();
        session.finish();
        return (hello.name() + " " + hello.version()).strip();
    }

    /** Ends every worker's process: its input is closed, and it is killed if it does not exit soon. */
    @Override
    public synchronized void close() {
        for (ProxyFactory f : workers) {
            f.close();
        }
        workers.clear();
    }
}
