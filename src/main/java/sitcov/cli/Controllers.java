package sitcov.cli;

import java.nio.file.Path;
import java.util.concurrent.atomic.AtomicInteger;
import sitcov.control.ControllerFactory;
import sitcov.control.ControllerSource;
import sitcov.protocol.ControllerChoice;
import sitcov.protocol.ControllerStartException;
import sitcov.protocol.ExecControllers;

/**
 * The controller a preset, {@code --controller} or {@code versions} names — {@code builtin},
 * {@code builtin:FAULTS} or {@code exec:COMMAND ARGS…} (README, "Test your own controller") — made
 * ready for an experiment's worker threads: a program is started and handshaken once before
 * anything runs, then each worker thread gets a process of its own, its stderr in
 * {@code controller-N.log} of the results folder.
 */
final class Controllers {
    private Controllers() {
    }

    /** The spec as given, once it names a controller sitcov can start. */
    static String check(String spec) throws UsageException {
        try {
            ControllerChoice.parse(spec);
            return spec.strip();
        } catch (IllegalArgumentException e) {
            throw new UsageException("controller: " + e.getMessage() + ".");
        }
    }

    /** Starts what {@code spec} names, handshaking a program at once; its logs go into {@code folder}. */
    static ControllerSource open(String spec, Path folder) throws UsageException {
        return open(spec, folder, "controller");
    }

    /** As {@link #open(String, Path)}, its logs named {@code LOGS-N.log}: several controllers share one folder. */
    static ControllerSource open(String spec, Path folder, String logs) throws UsageException {
        ControllerChoice choice;
        try {
            choice = ControllerChoice.parse(spec);
        } catch (IllegalArgumentException e) {
            throw new UsageException("controller: " + e.getMessage() + ".");
        }
        ControllerChoice.Workers workers = choice.open(Version.current(), ExecControllers.DEFAULT_TICK_TIMEOUT_MILLIS,
                ExecControllers.DEFAULT_HANDSHAKE_TIMEOUT_MILLIS);
        try {
            workers.check(null);
        } catch (ControllerStartException e) {
            workers.close();
            throw new UsageException(e.getMessage() + "; fix the controller's command (controller= or --controller).");
        }
        AtomicInteger threads = new AtomicInteger();
        ThreadLocal<ControllerFactory> perThread = ThreadLocal.withInitial(() -> workers.worker(
                choice instanceof ControllerChoice.Exec ? folder.resolve(logs + "-" + threads.incrementAndGet() + ".log")
                        : null));
        return new ControllerSource() {
            @Override
            public ControllerFactory forThisThread() {
                return perThread.get();
            }

            @Override
            public String spec() {
                return choice.text();
            }

            @Override
            public void close() {
                workers.close();
            }
        };
    }
}
