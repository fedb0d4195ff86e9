package sitcov.protocol;

import java.util.ArrayList;
import java.util.List;
import sitcov.control.Command;
import sitcov.control.ControllerBatch;
import sitcov.control.ControllerFailure;
import sitcov.control.ControllerFactory;
import sitcov.control.DeferredController;
import sitcov.control.Observation;
import sitcov.control.RunEnd;
import sitcov.control.RunStart;
import sitcov.faults.FaultSwitchboard;
import sitcov.faults.SeededControllerFactory;

/**
 * Batched lockstep (experiments/controllers/README.md, "Batches"): one controller process answers
 * up to B runs, each held by a slot 0..B-1. Each run's controller takes its tick's observation and
 * waits; {@link #send} sends the waiting observations in one message, {@link #receive} reads one
 * message of commands and hands each run its own. A run's observations and commands are those it
 * would have had alone: only the grouping differs, so its record is the same whatever B. All of it happens on the one
 * thread that steps the runs ({@code judge.BatchedRuns}), so the messages, too, come in an order
 * fixed by the seeds. A controller that fails (a timeout, an exit, a broken message) fails every
 * run waiting on it; the next run starts a fresh process. With B = 1 the messages are those of one
 * run at a time.
 */
public final class BatchingProxy implements ControllerBatch, AutoCloseable {
    private final ProxyFactory.Connector connector;
    private final long tickTimeoutMillis;
    private final int batch;
    private final List<Slot> waiting = new ArrayList<>();
    private final java.util.ArrayDeque<Sent> outstanding = new java.util.ArrayDeque<>();
    /** The runs the last exchange answered: a broken command fails those that have not read theirs. */
    private List<Slot> answered = List.of();
    /** Why the controller failed, for the runs that observe after it did. */
    private ControllerFailure broken;
    private Session session;

    private BatchingProxy(ProxyFactory.Connector connector, long tickTimeoutMillis, int maxBatch)
            throws ControllerStartException {
        this.connector = connector;
        this.tickTimeoutMillis = tickTimeoutMillis;
        this.session = connector.connect();
        this.batch = Math.max(1, Math.min(maxBatch, session.hello().batch()));
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

    @Override
    public int size() {
        return batch;
    }

    @Override
    public ControllerFactory slot(int slot) {
        if (slot < 0 || slot >= batch) {
            throw new IllegalArgumentException("slot " + slot + " of a batch of " + batch);
        }
        return (SeededControllerFactory) (run, faults) -> start(slot, run, faults);
    }

    private DeferredController start(int slot, RunStart run, FaultSwitchboard faults) {
        if (session == null || session.isDead()) {
            try {
                session = connector.connect();
            } catch (ControllerStartException e) {
                session = null;
                return failed(e.getMessage());
            }
        }
        boolean sent = batch == 1 ? session.reset(run, faults.activeFaults())
                : session.reset(run, faults.activeFaults(), slot);
        return sent ? new Slot(session, slot, faults) : failed("the controller could not be sent the run's reset");
    }

    @Override
    public void send() {
        if (waiting.isEmpty()) {
            return;
        }
        Sent sent = new Sent(List.copyOf(waiting));
        waiting.clear();
        outstanding.addLast(sent);
        Session s = sent.asked.get(0).session;
        try {
            if (batch == 1) {
                s.sendOne(sent.asked.get(0).now, tickTimeoutMillis);
            } else {
                s.sendBatch(sent.observations(), sent.slots, tickTimeoutMillis);
            }
        } catch (ControllerFailure f) {
            failAll(f);
        }
    }

    @Override
    public void receive() {
        Sent sent = outstanding.pollFirst();
        if (sent == null) {
            return;
        }
        answered = sent.asked;
        if (sent.asked.get(0).failure != null) {
            return;
        }
        Session s = sent.asked.get(0).session;
        long tick = sent.asked.get(0).now.tick();
        try {
            if (batch == 1) {
                Slot only = sent.asked.get(0);
                String line = s.receiveBatch(tick, tickTimeoutMillis);
                only.line = line;
                try {
                    only.answer(Message.parse(line), null);
                } catch (ProtocolException e) {
                    throw s.error("at tick " + tick + " it wrote " + Message.shorten(line) + ": " + e.getMessage());
                }
                return;
            }
            answerAll(s, sent, s.receiveBatch(tick, tickTimeoutMillis));
        } catch (ControllerFailure f) {
            failAll(f);
        }
    }

    /** The controller failed: every run waiting for or holding an unread command fails with {@code f}. */
    private void failAll(ControllerFailure f) {
        broken = f;
        for (Slot slot : answered) {
            if (slot.failure == null && (slot.command != null || slot.now != null)) {
                slot.answer(null, f);
            }
        }
        for (Sent sent : outstanding) {
            for (Slot slot : sent.asked) {
                slot.answer(null, f);
            }
        }
        for (Slot slot : waiting) {
            slot.answer(null, f);
        }
    }

    /** Hands out the commands of {@code line}, the answer to {@code sent}. */
    private void answerAll(Session s, Sent sent, String line) {
        long tick = sent.asked.get(0).now.tick();
        Message m;
        List<Object> items;
        try {
            m = Message.parse(line);
            m.expect("commands");
            items = m.list("items");
        } catch (ProtocolException e) {
            throw s.error("at tick " + tick + " it wrote " + Message.shorten(line) + ": " + e.getMessage());
        }
        if (items.size() != sent.asked.size()) {
            throw s.error("at tick " + tick + " it wrote " + items.size() + " commands for " + sent.asked.size()
                    + " observations: " + Message.shorten(line));
        }
        List<Message> commands = new ArrayList<>(items.size());
        for (int i = 0; i < items.size(); i++) {
            try {
                Message item = m.messageAt(items, i, "items");
                long run = item.integer("run");
                if (run != sent.slots[i]) {
                    throw new ProtocolException("commands.items[" + i + "] answers run " + run + ", the observation was run "
                            + sent.slots[i] + "'s (commands come in the order of the observations)");
                }
                commands.add(item);
            } catch (ProtocolException e) {
                throw s.error("at tick " + tick + " it wrote " + Message.shorten(line) + ": " + e.getMessage());
            }
        }
        for (int i = 0; i < sent.asked.size(); i++) {
            sent.asked.get(i).answer(commands.get(i), null);
        }
    }

    /** A message sent and not yet answered: its runs, in slot order. */
    private static final class Sent {
        final List<Slot> asked;
        final int[] slots;

        Sent(List<Slot> waiting) {
            List<Slot> inOrder = new ArrayList<>(waiting);
            inOrder.sort((a, b) -> Integer.compare(a.slot, b.slot));
            this.asked = List.copyOf(inOrder);
            this.slots = new int[inOrder.size()];
            for (int i = 0; i < slots.length; i++) {
                slots[i] = inOrder.get(i).slot;
            }
        }

        List<Observation> observations() {
            List<Observation> now = new ArrayList<>(asked.size());
            for (Slot slot : asked) {
                now.add(slot.now);
            }
            return now;
        }
    }

    @Override
    public void close() {
        if (session != null) {
            session.finish();
            session = null;
        }
    }

    /** A controller that could not be started: the run ends at its first tick with its reason. */
    private static DeferredController failed(String why) {
        return new DeferredController() {
            @Override
            public void observe(Observation now) {
                throw new ControllerFailure(ControllerFailure.Kind.ERROR, why);
            }

            @Override
            public void step(Observation now, Command out) {
                throw new ControllerFailure(ControllerFailure.Kind.ERROR, why);
            }
        };
    }

    /** One run's controller: its observation waits for the next exchange, its step reads the answer. */
    private final class Slot implements DeferredController {
        private final Session session;
        private final int slot;
        private final FaultSwitchboard faults;
        private Observation now;
        private Message command;
        /** The line its command came in, one run at a time (B = 1), for the message of a wrong one. */
        private String line;
        private ControllerFailure failure;

        Slot(Session session, int slot, FaultSwitchboard faults) {
            this.session = session;
            this.slot = slot;
            this.faults = faults;
        }

        @Override
        public java.util.Set<sitcov.control.Sensor> sensors() {
            return session.hello() == null ? java.util.Set.of() : session.hello().sensors();
        }

        @Override
        public void observe(Observation observation) {
            if (session.isDead()) {
                throw broken != null ? broken
                        : new ControllerFailure(ControllerFailure.Kind.ERROR, "the controller failed earlier in this run");
            }
            now = observation;
            command = null;
            failure = null;
            waiting.add(this);
        }

        void answer(Message command, ControllerFailure failure) {
            this.command = command;
            this.failure = failure;
        }

        @Override
        public void step(Observation observation, Command out) {
            if (command == null && failure == null) {
                // stepped without an exchange (a plain loop): it is answered alone
                if (now != observation) {
                    observe(observation);
                }
                send();
                while (command == null && failure == null && !outstanding.isEmpty()) {
                    receive();
                }
            }
            if (failure != null) {
                throw failure;
            }
            Message item = command;
            command = null;
            now = null;
            boolean echoes = batch > 1 || session.hello().echoesTicks();
            try {
                Wire.command(item, observation.tick(), echoes, session.hello().seededFaults(), out, faults);
            } catch (ProtocolException e) {
                ControllerFailure f = session.error("at tick " + observation.tick() + (batch > 1 ? " its command for run "
                        + slot + " is wrong: " : " it wrote " + Message.shorten(line) + ": ") + e.getMessage());
                failAll(f);
                throw f;
            }
        }

        @Override
        public void end(RunEnd how) {
            if (batch == 1) {
                session.end(how);
            } else {
                session.end(how, slot);
            }
        }
    }
}
