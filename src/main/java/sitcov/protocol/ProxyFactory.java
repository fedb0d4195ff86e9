package sitcov.protocol;

import sitcov.control.Controller;
import sitcov.control.RunStart;
import sitcov.faults.FaultSwitchboard;
import sitcov.faults.SeededControllerFactory;

/**
 * One worker thread's controller program: connected at its first run, reused run after run, and
 * connected afresh after it failed. A run whose controller cannot be started ends at its first
 * tick with CONTROLLER_ERROR and the reason; the experiment goes on. The run's faults go out with
 * its reset, and the activations the program reports come back onto the run's board: a program
 * may serve a controller with seeded faults ({@code sitcov controller builtin}).
 */
public final class ProxyFactory implements SeededControllerFactory, AutoCloseable {
    /** Makes a fresh, handshaken session: starts a process, or connects a pair of streams. */
    @FunctionalInterface
    interface Connector {
        Session connect() throws ControllerStartException;
    }

    private final Connector connector;
    private final long tickTimeoutMillis;
    private Session session;

    ProxyFactory(Connector connector, long tickTimeoutMillis) {
        this.connector = connector;
        this.tickTimeoutMillis = tickTimeoutMillis;
    }

    @Override
    public Controller start(RunStart run, FaultSwitchboard faults) {
        // a controller that went away between runs (its write fails) gets one fresh start
        for (int attempt = 0; attempt < 2; attempt++) {
            if (session == null || session.isDead()) {
                try {
                    session = connector.connect();
                } catch (ControllerStartException e) {
                    session = null;
                    return ProxyController.failed(e.getMessage());
                }
            }
            if (session.reset(run, faults.activeFaults())) {
                return new ProxyController(session, faults, tickTimeoutMillis);
            }
        }
        return ProxyController.failed("the controller could not be sent the run's reset");
    }

    /** The controller's hello, once it is connected (null before). */
    public String describe() {
        return session == null || session.hello() == null ? null
                : (session.hello().name() + " " + session.hello().version()).strip();
    }

    /** Closes the controller's input (it exits at the end of its input) and lets it go. */
    @Override
    public void close() {
        if (session != null) {
            session.finish();
            session = null;
        }
    }
}
