package sitcov.protocol;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.BiFunction;
import sitcov.control.Command;
import sitcov.control.Controller;
import sitcov.control.ControllerFailure;
import sitcov.control.Observation;
import sitcov.control.RunEnd;
import sitcov.control.RunStart;
import sitcov.faults.FaultSwitchboard;
import sitcov.faults.SeededControllerFactory;

/**
 * Batched lockstep (experiments/controllers/README.md, "The protocol"): one controller process steps up to B runs
 * together.
 * Each run is stepped on a thread of its own, in a slot 0..B-1; its controller's {@code step}
 * waits until every run of the slots that are in a run has asked for its command (or ended), and
 * the last to ask sends their observations in one message, reads one message of commands, and
 * hands each run its own. A run's observations and commands are those it would have had alone:
 * only the grouping differs, so its record is the same whatever B. A controller that fails (a
 * timeout, an exit, a broken message) fails every run of the batch; the next run starts a fresh
 * process.
 */
public final class BatchingProxy implements AutoCloseable {
    private final ProxyFactory.Connector connector;
    private final long tickTimeoutMillis;
    private final int batch;
    private Group group;

    private BatchingProxy(ProxyFactory.Connector connector, long tickTimeoutMillis, int maxBatch)
            throws ControllerStartException {
        this.connector = connector;
        this.tickTimeoutMillis = tickTimeoutMillis;
        Session first = connector.connect();
        this.group = new Group(first, tickTimeoutMillis);
        this.batch = Math.max(1, Math.min(maxBatch, first.hello().batch()));
    }

    /**
     * Starts the controller and handshakes: runs are batched by the smaller of {@code maxBatch} and
     * the batch the controller's hello takes.
     */
    static BatchingProxy open(ProxyFactory.Connector connector, long tickTimeoutMillis, int maxBatch)
            throws ControllerStartException {
        return new BatchingProxy(connector, tickTimeoutMillis, maxBatch);
    }

    /** How many runs are stepped together: 1 when the controller takes one at a time. */
    public int batch() {
        return batch;
    }

    /**
     * Runs {@code count} runs, {@link #batch} at a time on as many threads: {@code run.apply(i,
     * factory)} runs run i with the controller factory of the slot it is given. The results in the
     * order of i.
     */
    public <T> List<T> runAll(int count, BiFunction<Integer, SeededControllerFactory, T> run) {
        List<T> results = new ArrayList<>(java.util.Collections.nCopies(count, null));
        AtomicInteger next = new AtomicInteger();
        RuntimeException[] thrown = new RuntimeException[1];
        int threads = Math.min(batch, count);
        List<Thread> workers = new ArrayList<>();
        // the threads end together: a thread that wrote to the controller stays until the last run is done
        java.util.concurrent.CountDownLatch done = new java.util.concurrent.CountDownLatch(threads);
        for (int t = 0; t < threads; t++) {
            int slot = t;
            SeededControllerFactory factory = (start, faults) -> start(slot, start, faults);
            Thread worker = new Thread(() -> {
                try {
                    for (int i = next.getAndIncrement(); i < count; i = next.getAndIncrement()) {
                        try {
                            results.set(i, run.apply(i, factory));
                        } finally {
                            leave(slot);
                        }
                    }
                } catch (RuntimeException | Error e) {
                    synchronized (thrown) {
                        if (thrown[0] == null) {
                            thrown[0] = e instanceof RuntimeException r ? r : new IllegalStateException(e);
                        }
                    }
                    next.set(count);
                } finally {
                    done.countDown();
                    try {
                        done.await();
                    } catch (InterruptedException e) {
                        Thread.currentThread().interrupt();
                    }
                }
            }, "sitcov-batch-" + slot);
            workers.add(worker);
            worker.start();
        }
        for (Thread worker : workers) {
            try {
                worker.join();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new IllegalStateException("interrupted while batched runs ran", e);
            }
        }
        if (thrown[0] != null) {
            throw thrown[0];
        }
        return results;
    }

    private Controller start(int slot, RunStart run, FaultSwitchboard faults) {
        Group g;
        synchronized (this) {
            if (group == null || group.session.isDead()) {
                try {
                    group = new Group(connector.connect(), tickTimeoutMillis);
                } catch (ControllerStartException e) {
                    group = null;
                    return ProxyController.failed(e.getMessage());
                }
            }
            g = group;
        }
        if (batch == 1) {
            // one run at a time: today's messages, as a plain worker would send them
            return g.session.reset(run, faults.activeFaults()) ? new ProxyController(g.session, faults, tickTimeoutMillis)
                    : ProxyController.failed("the controller could not be sent the run's reset");
        }
        if (!g.begin(slot, run, faults.activeFaults())) {
            return ProxyController.failed("the controller could not be sent the run's reset");
        }
        return new Controller() {
            @Override
            public void step(Observation now, Command out) {
                Message item = g.step(slot, now);
                try {
                    Wire.command(item, now.tick(), true, g.session.hello().seededFaults(), out, faults);
                } catch (ProtocolException e) {
                    throw g.fail("at tick " + now.tick() + " its command for run " + slot + " is wrong: " + e.getMessage());
                }
            }

            @Override
            public void end(RunEnd how) {
                g.end(slot, how);
            }
        };
    }

    /** A slot's thread is done with its run, however it ended: its slot is no longer waited for. */
    private void leave(int slot) {
        Group g;
        synchronized (this) {
            g = group;
        }
        if (g != null) {
            g.leave(slot);
        }
    }

    @Override
    public synchronized void close() {
        if (group != null) {
            group.session.finish();
            group = null;
        }
    }

    /** One process's batch: the slots in a run, and the observations waiting for their commands. */
    private static final class Group {
        private final Session session;
        private final boolean[] live = new boolean[Wire.MAX_BATCH];
        private int liveCount;
        private final List<Waiting> waiting = new ArrayList<>();
        private ControllerFailure failure;

        private final long timeoutMillis;

        Group(Session session, long timeoutMillis) {
            this.session = session;
            this.timeoutMillis = timeoutMillis;
        }

        synchronized boolean begin(int slot, RunStart run, java.util.Set<sitcov.faults.Fault> faults) {
            if (!session.reset(run, faults, slot)) {
                return false;
            }
            live[slot] = true;
            liveCount++;
            return true;
        }

        /** Waits, parked outside the lock, until the batch of this run's observation is answered. */
        Message step(int slot, Observation now) {
            Waiting w = new Waiting(slot, now);
            synchronized (this) {
                if (failure != null) {
                    throw failure;
                }
                waiting.add(w);
                if (waiting.size() >= liveCount) {
                    send();
                }
            }
            while (!w.done) {
                java.util.concurrent.locks.LockSupport.park(this);
                if (Thread.interrupted()) {
                    Thread.currentThread().interrupt();
                    throw new ControllerFailure(ControllerFailure.Kind.ERROR, "interrupted while waiting for a command");
                }
            }
            if (w.failure != null) {
                throw w.failure;
            }
            return w.command;
        }

        synchronized void end(int slot, RunEnd how) {
            session.end(how, slot);
            leave(slot);
        }

        synchronized void leave(int slot) {
            if (live[slot]) {
                live[slot] = false;
                liveCount--;
                if (!waiting.isEmpty() && waiting.size() >= liveCount) {
                    send();
                }
            }
        }

        /** Sends the waiting observations, reads their commands, and wakes their runs. */
        private void send() {
            List<Waiting> batch = new ArrayList<>(waiting);
            waiting.clear();
            batch.sort((a, b) -> Integer.compare(a.slot, b.slot));
            List<Observation> observations = new ArrayList<>(batch.size());
            int[] slots = new int[batch.size()];
            for (int i = 0; i < batch.size(); i++) {
                observations.add(batch.get(i).now);
                slots[i] = batch.get(i).slot;
            }
            try {
                String line = session.stepBatch(observations, slots, timeoutMillis);
                Message m;
                List<Object> items;
                try {
                    m = Message.parse(line);
                    m.expect("commands");
                    items = m.list("items");
                } catch (ProtocolException e) {
                    throw fail("at tick " + observations.get(0).tick() + " it wrote " + Message.shorten(line) + ": "
                            + e.getMessage());
                }
                if (items.size() != batch.size()) {
                    throw fail("at tick " + observations.get(0).tick() + " it wrote " + items.size()
                            + " commands for " + batch.size() + " observations: " + Message.shorten(line));
                }
                List<Message> commands = new ArrayList<>(items.size());
                for (int i = 0; i < items.size(); i++) {
                    try {
                        Message item = m.messageAt(items, i, "items");
                        long run = item.integer("run");
                        if (run != slots[i]) {
                            throw new ProtocolException("commands.items[" + i + "] answers run " + run
                                    + ", the observation was run " + slots[i] + "'s (commands come in the order of the"
                                    + " observations)");
                        }
                        commands.add(item);
                    } catch (ProtocolException e) {
                        throw fail("at tick " + observations.get(0).tick() + " it wrote " + Message.shorten(line) + ": "
                                + e.getMessage());
                    }
                }
                for (int i = 0; i < batch.size(); i++) {
                    batch.get(i).answer(commands.get(i), null);
                }
            } catch (ControllerFailure f) {
                failure = f;
                for (Waiting w : batch) {
                    w.answer(null, f);
                }
            }
        }

        /** The controller broke the protocol: it is killed, and every run of the batch fails with the reason. */
        synchronized ControllerFailure fail(String why) {
            ControllerFailure f = session.error(why);
            failure = f;
            for (Waiting w : waiting) {
                w.answer(null, f);
            }
            waiting.clear();
            return f;
        }
    }

    private static final class Waiting {
        final int slot;
        final Observation now;
        final Thread thread = Thread.currentThread();
        Message command;
        ControllerFailure failure;
        volatile boolean done;

        Waiting(int slot, Observation now) {
            this.slot = slot;
            this.now = now;
        }

        /** Hands the run its command, or the failure, and wakes it (when it is not the thread answering). */
        void answer(Message command, ControllerFailure failure) {
            if (done) {
                return;
            }
            this.command = command;
            this.failure = failure;
            done = true;
            if (thread != Thread.currentThread()) {
                java.util.concurrent.locks.LockSupport.unpark(thread);
            }
        }
    }
}
