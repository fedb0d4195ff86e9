package sitcov.engine;

import java.util.function.LongSupplier;
import java.util.random.RandomGenerator;

/**
 * The state of one simulation run: its schedule and its named random streams, both derived from
 * one seed. Models keep their own state and hand it to their agents; this object only owns what
 * every model needs, so it stays small and final (composition, not MASON's subclassing).
 */
public final class SimState implements LongSupplier {
    /** The stream that orders agents of equal ordering within a tick. */
    public static final String SCHEDULE_STREAM = "schedule";

    private RandomStreams streams;
    private Schedule schedule;

    public SimState(long seed) {
        this.streams = new RandomStreams(seed);
        this.schedule = new Schedule(streams.stream(SCHEDULE_STREAM));
    }

    public long seed() {
        return streams.root();
    }

    public Schedule schedule() {
        return schedule;
    }

    public RandomStreams streams() {
        return streams;
    }

    /** The named stream {@code label} of this run; the same label always gives the same stream object. */
    public RandomGenerator random(String label) {
        return streams.stream(label);
    }

    /** Runs every event of the next scheduled tick; false when nothing is left to run. */
    public boolean step() {
        return schedule.step(this);
    }

    /** The last tick that ran, or {@link Schedule#BEFORE_SIMULATION}. */
    public long tick() {
        return schedule.time();
    }

    /** The tick, for whatever stamps events with it; the state itself rather than a lambda, so a checkpoint copies it. */
    @Override
    public long getAsLong() {
        return tick();
    }
}
