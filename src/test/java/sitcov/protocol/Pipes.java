package sitcov.protocol;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.io.PipedInputStream;
import java.io.PipedOutputStream;
import java.io.UncheckedIOException;
import java.util.Set;
import sitcov.control.ControllerFactory;
import sitcov.faults.Fault;

/** A controller on a thread of its own, connected to sitcov's side by pipes: the protocol without a process. */
final class Pipes {
    private Pipes() {
    }

    /** The controller's side: reads sitcov's messages from {@code in}, writes its own to {@code out}. */
    @FunctionalInterface
    interface Peer {
        void serve(InputStream in, OutputStream out) throws IOException, ProtocolException;
    }

    /** A worker's factory whose controller is {@code served}, served over the newest protocol in process. */
    static ProxyFactory serving(ControllerFactory served, Set<Fault> extraFaults) {
        return serving(served, extraFaults, Wire.PROTOCOL);
    }

    /** The same, the server answering with at most protocol {@code newestProtocol}. */
    static ProxyFactory serving(ControllerFactory served, Set<Fault> extraFaults, int newestProtocol) {
        return connecting((in, out) -> new ControllerServer(served, "in-process", "test", extraFaults, newestProtocol)
                .serve(in, out));
    }

    /** A worker's factory whose controller is {@code peer}, started afresh on a thread for every connection. */
    static ProxyFactory connecting(Peer peer) {
        return new ProxyFactory(() -> connect(peer), 60_000);
    }

    /**
     * Runs batched by up to {@code maxBatch} over one in-process server of {@code served} that
     * takes up to {@code serverBatch} runs a message.
     */
    static BatchingProxy batching(ControllerFactory served, int serverBatch, int maxBatch) throws ControllerStartException {
        return batching((in, out) -> new ControllerServer(served, "in-process", "test", Set.of(), Wire.PROTOCOL, serverBatch)
                .serve(in, out), maxBatch);
    }

    /** Runs batched by up to {@code maxBatch} over {@code peer}, started afresh on a thread for every connection. */
    static BatchingProxy batching(Peer peer, int maxBatch) throws ControllerStartException {
        return BatchingProxy.open(() -> connect((in, out) -> {
            try {
                peer.serve(in, out);
            } catch (IOException e) {
                // a piped stream is tied to the thread that last wrote to it: once the batch's threads are done,
                // before sitcov closes the pipe, a read finds that thread gone; as an end of input here
                if (!"Write end dead".equals(e.getMessage())) {
                    throw e;
                }
            }
        }), 60_000, maxBatch);
    }

    static Session connect(Peer peer) throws ControllerStartException {
        try {
            PipedOutputStream toServer = new PipedOutputStream();
            PipedInputStream serverIn = new PipedInputStream(toServer, 1 << 16);
            PipedOutputStream toSitcov = new PipedOutputStream();
            PipedInputStream sitcovIn = new PipedInputStream(toSitcov, 1 << 16);
            Thread server = new Thread(() -> {
                try (toSitcov) {
                    peer.serve(serverIn, toSitcov);
                } catch (IOException | ProtocolException e) {
                    throw new IllegalStateException(e);
                }
            }, "controller-peer");
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
