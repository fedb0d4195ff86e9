package sitcov.protocol;

import java.io.IOException;
import java.util.Set;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.Supplier;
import sitcov.control.ControllerFailure;
import sitcov.control.Observation;
import sitcov.control.RunEnd;
import sitcov.control.RunStart;
import sitcov.faults.Fault;

/**
 * sitcov's side of one connection to a controller, after a successful handshake: it sends resets,
 * observations and ends, and reads commands within the per-tick timeout. Once it failed (a timeout,
 * an exit, garbage, a write that broke) it is dead: its controller is killed and it sends nothing
 * more.
 */
final class Session implements AutoCloseable {
    private static final int IDLE = 0;
    private static final int WAITING = 1;
    private static final int TIMED_OUT = 2;

    private final String shown;
    private final Lines lines;
    private final Runnable kill;
    private final Runnable reap;
    private final Supplier<String> stderrTail;
    private final Supplier<String> exitStatus;
    private final JsonWriter writer = new JsonWriter();
    private final AtomicInteger state = new AtomicInteger(IDLE);
    private volatile long deadline;
    /** When each message still waiting for its answer was sent, oldest first (a ring). */
    private final long[] sentAt = new long[2];
    private int oldest;
    private int unanswered;
    private Wire.Hello hello;
    private boolean dead;
    private boolean inRun;

    /**
     * @param shown      the controller as messages name it, e.g. {@code `python3 x.py`}
     * @param kill       ends the controller, so that a blocked read returns
     * @param reap       after its input was closed: waits a little for it to exit, then kills what is left
     * @param stderrTail the last lines it wrote to stderr ("" when none are kept)
     */
    Session(String shown, Lines lines, Runnable kill, Runnable reap, Supplier<String> stderrTail) {
        this(shown, lines, kill, reap, stderrTail, () -> "");
    }

    /**
     * @param exitStatus how the program ended once its output did, e.g. " with exit code 3" ("" when
     *                   unknown or it has not exited)
     */
    Session(String shown, Lines lines, Runnable kill, Runnable reap, Supplier<String> stderrTail,
            Supplier<String> exitStatus) {
        this.shown = shown;
        this.lines = lines;
        this.kill = kill;
        this.reap = reap;
        this.stderrTail = stderrTail;
        this.exitStatus = exitStatus;
    }

    /** Sends sitcov's hello and reads the controller's within {@code timeoutMillis}. */
    Wire.Hello handshake(String sitcovVersion, long timeoutMillis) throws ControllerStartException {
        Deadlines.watch(this);
        Wire.sitcovHello(writer, sitcovVersion);
        String line;
        try {
            line = exchange(timeoutMillis);
        } catch (IOException e) {
            // a broken pipe: it went away before it read sitcov's hello
            throw startFailure(state.get() == TIMED_OUT ? "no hello within " + timeoutMillis + " ms"
                    : "it exited before its hello");
        }
        if (state.get() == TIMED_OUT) {
            throw startFailure("no hello within " + timeoutMillis + " ms");
        }
        if (line == null) {
            throw startFailure("it exited before its hello");
        }
        try {
            hello = Wire.controllerHello(Message.parse(line));
        } catch (ProtocolException e) {
            throw startFailure(e.getMessage());
        }
        return hello;
    }

    private ControllerStartException startFailure(String why) {
        close();
        String tail = stderrTail.get();
        return new ControllerStartException("controller " + shown + " failed the handshake: " + why
                + (tail.isEmpty() ? "" : "; its stderr ends: " + tail));
    }

    Wire.Hello hello() {
        return hello;
    }

    boolean isDead() {
        return dead;
    }

    /** Starts a run with {@code faults} switched on; false when the controller could not be written to (it is then dead). */
    boolean reset(RunStart run, Set<Fault> faults) {
        if (inRun) {
            end(new RunEnd("STOPPED", -1));
        }
        ResetMessage.write(writer, run, faults);
        try {
            lines.write(writer);
            inRun = true;
            return true;
        } catch (IOException e) {
            close();
            return false;
        }
    }

    /** Sends the observation and returns the command's line; a timeout, exit or broken pipe is a failure. */
    String step(Observation now, long timeoutMillis) {
        if (dead) {
            throw new ControllerFailure(ControllerFailure.Kind.ERROR, "controller " + shown + " failed earlier in this run");
        }
        Wire.observation(writer, now, hello);
        return answer(now.tick(), timeoutMillis);
    }

    /**
     * Sends the observations of several runs in one message ({@code slots[i]} is the slot of
     * {@code now.get(i)}) and returns the line of their commands; failures as {@link #step}.
     */
    String stepBatch(java.util.List<Observation> now, int[] slots, long timeoutMillis) {
        sendBatch(now, slots, timeoutMillis);
        return receiveBatch(now.get(0).tick(), timeoutMillis);
    }

    /**
     * Sends the observations of several runs in one message without waiting for the answer, so
     * that sitcov steps other runs while the controller works; {@link #receiveBatch} reads the
     * answers in the order the messages went. The deadline of the oldest message not yet answered
     * is the one armed.
     */
    void sendBatch(java.util.List<Observation> now, int[] slots, long timeoutMillis) {
        checkAlive();
        Wire.observations(writer, now, slots, hello);
        send(now.get(0).tick(), timeoutMillis);
    }

    /** As {@link #sendBatch}, one run's observation in today's message of one run at a time. */
    void sendOne(Observation now, long timeoutMillis) {
        checkAlive();
        Wire.observation(writer, now, hello);
        send(now.tick(), timeoutMillis);
    }

    private void checkAlive() {
        if (dead) {
            throw new ControllerFailure(ControllerFailure.Kind.ERROR, "controller " + shown + " failed earlier in this run");
        }
    }

    /** Writes the message in the writer, arming its deadline if no earlier message waits for its answer. */
    private void send(long tick, long timeoutMillis) {
        long sent = System.nanoTime();
        if (unanswered == sentAt.length) {
            throw new IllegalStateException("at most " + sentAt.length + " messages may wait for their answers");
        }
        sentAt[(oldest + unanswered) % sentAt.length] = sent;
        if (unanswered++ == 0) {
            deadline = sent + timeoutMillis * 1_000_000;
            state.set(WAITING);
        }
        try {
            lines.write(writer);
        } catch (IOException e) {
            if (state.get() == TIMED_OUT) {
                throw timeout(tick, timeoutMillis);
            }
            throw error("it exited" + exitStatus.get() + " or closed its input before the observation of tick "
                    + tick + " (" + e.getMessage() + ")");
        }
    }

    /** Reads the line answering the oldest message {@link #sendBatch} sent (its first observation of {@code tick}). */
    String receiveBatch(long tick, long timeoutMillis) {
        String line;
        try {
            line = lines.read();
        } catch (IOException e) {
            line = null;
        }
        oldest = (oldest + 1) % sentAt.length;
        unanswered--;
        if (unanswered > 0) {
            // the next message's own deadline, unless the controller ran out of time meanwhile
            deadline = sentAt[oldest] + timeoutMillis * 1_000_000;
        } else if (!state.compareAndSet(WAITING, IDLE)) {
            line = null;
        }
        if (state.get() == TIMED_OUT) {
            throw timeout(tick, timeoutMillis);
        }
        if (line == null) {
            throw error("it exited" + exitStatus.get() + " at tick " + tick + " instead of answering the observations");
        }
        return line;
    }

    /** Writes the message in the writer and reads the answer to the observation(s) of {@code tick}. */
    private String answer(long tick, long timeoutMillis) {
        String line;
        try {
            line = exchange(timeoutMillis);
        } catch (IOException e) {
            if (state.get() == TIMED_OUT) {
                throw timeout(tick, timeoutMillis);
            }
            throw error("it exited" + exitStatus.get() + " or closed its input before the observation of tick "
                    + tick + " (" + e.getMessage() + ")");
        }
        if (state.get() == TIMED_OUT) {
            throw timeout(tick, timeoutMillis);
        }
        if (line == null) {
            throw error("it exited" + exitStatus.get() + " at tick " + tick + " instead of answering the observation");
        }
        return line;
    }

    /** Starts the run of a batch's {@code slot}; false when the controller could not be written to (it is then dead). */
    boolean reset(RunStart run, Set<Fault> faults, int slot) {
        ResetMessage.write(writer, run, faults, slot);
        return writeOrDie();
    }

    /** Tells the controller how the run of a batch's {@code slot} ended (no answer is read). */
    void end(RunEnd how, int slot) {
        if (dead) {
            return;
        }
        Wire.end(writer, how, slot);
        writeOrDie();
    }

    private boolean writeOrDie() {
        try {
            lines.write(writer);
            return true;
        } catch (IOException e) {
            close();
            return false;
        }
    }

    private ControllerFailure timeout(long tick, long timeoutMillis) {
        close();
        return new ControllerFailure(ControllerFailure.Kind.TIMEOUT,
                "controller " + shown + " gave no command within " + timeoutMillis + " ms at tick " + tick);
    }

    /** The controller broke the protocol or went away: it is killed; the failure carries its stderr's tail. */
    ControllerFailure error(String why) {
        close();
        String tail = stderrTail.get();
        return new ControllerFailure(ControllerFailure.Kind.ERROR, "controller " + shown + ": " + why
                + (tail.isEmpty() ? "" : "; its stderr ends: " + tail));
    }

    /** Tells the controller how the run ended (no answer is read). */
    void end(RunEnd how) {
        inRun = false;
        if (dead) {
            return;
        }
        Wire.end(writer, how);
        try {
            lines.write(writer);
        } catch (IOException e) {
            close();
        }
    }

    /** Writes the message in {@code writer} and reads a line, with the deadline armed. */
    private String exchange(long timeoutMillis) throws IOException {
        deadline = System.nanoTime() + timeoutMillis * 1_000_000;
        state.set(WAITING);
        lines.write(writer);
        String line = lines.read();
        return state.compareAndSet(WAITING, IDLE) ? line : null;
    }

    /** Called by {@link Deadlines}: kills a controller that is past its deadline. */
    void checkDeadline(long now) {
        if (state.get() == WAITING && now - deadline > 0 && state.compareAndSet(WAITING, TIMED_OUT)) {
            kill.run();
        }
    }

    /** Kills the controller; the session is dead. */
    @Override
    public void close() {
        dead = true;
        Deadlines.forget(this);
        kill.run();
    }

    /** Ends the session politely: the controller's input is closed, and it is expected to exit. */
    void finish() {
        dead = true;
        Deadlines.forget(this);
        try {
            lines.closeOutput();
        } catch (IOException e) {
            // it is going away either way
        }
        reap.run();
    }
}
