package sitcov.protocol;

import java.io.IOException;
import java.io.PipedInputStream;
import java.io.PipedOutputStream;
import java.io.UncheckedIOException;
import java.util.Set;
import sitcov.control.ControllerFactory;
import sitcov.faults.Fault;

/** A {@link ControllerServer} on a thread of its own, connected to sitcov's side by pipes: the protocol without a process. */
final class Pipes {
    private Pipes() {
    }

    /** A worker's factory whose controller is {@code served}, served over the protocol in process. */
    static ProxyFactory serving(ControllerFactory served, Set<Fault> extraFaults) {
        return new ProxyFactory(() -> connect(served, extraFaults), 60_000);
    }

    private static Session connect(ControllerFactory served, Set<Fault> extraFaults) throws ControllerStartException {
        try {
            PipedOutputStream toServer = new PipedOutputStream();
            PipedInputStream serverIn = new PipedInputStream(toServer, 1 << 16);
            PipedOutputStream toSitcov = new PipedOutputStream();
            PipedInputStream sitcovIn = new PipedInputStream(toSitcov, 1 << 16);
            Thread server = new Thread(() -> {
                try (toSitcov) {
                    new ControllerServer(served, "in-process", "test", extraFaults).serve(serverIn, toSitcov);
                } catch (IOException | ProtocolException e) {
                    throw new IllegalStateException(e);
                }
            }, "controller-server");
            server.setDaemon(true);
            server.start();
            Runnable close = () -> {
                try {
                    toServer.close();
                } catch (IOException e) {
                    throw new UncheckedIOException(e);
                }
            };
            Session session = new Session("`in-process`", new Lines(sitcovIn, toServer), close, close, () -> "");
            session.handshake("test", 60_000);
            return session;
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
