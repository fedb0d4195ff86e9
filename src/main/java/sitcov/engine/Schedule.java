package sitcov.engine;

import java.util.ArrayList;
import java.util.List;
import java.util.PriorityQueue;
import java.util.random.RandomGenerator;

/**
 * A discrete-time schedule in the manner of MASON's {@code sim.engine.Schedule}. Events are kept
 * in order of (tick, ordering); events of the same tick and ordering run in an order shuffled
 * afresh every tick from the schedule's own random stream, so no agent is always first and the
 * order is still fixed by the seed.
 *
 * <p>Time is a whole tick ({@code long}); {@link #BEFORE_SIMULATION} until the first tick runs.
 * An event may only be scheduled for a tick after the current one. Not thread-safe: one schedule
 * belongs to one run.
 */
public final class Schedule {
    /** The time before any tick has run. */
    public static final long BEFORE_SIMULATION = -1;

    private RandomGenerator shuffle;
    private PriorityQueue<Event> queue = new PriorityQueue<>();
    private List<Event> due = new ArrayList<>();
    private long time = BEFORE_SIMULATION;
    private long nextSequence;
    /** Bumped by {@link #clear()} so a tick in progress knows to stop. */
    private long generation;
    /** Set by {@link #pause} while an agent steps. */
    private boolean pauseAsked;
    /** The index in {@link #due} of the agent that paused the tick in progress, or -1. */
    private int pausedAt = -1;

    public Schedule(RandomGenerator shuffle) {
        this.shuffle = shuffle;
    }

    /** The last tick that ran, or {@link #BEFORE_SIMULATION}. */
    public long time() {
        return time;
    }

    /** True when no event remains to run. */
    public boolean isEmpty() {
        return queue.isEmpty();
    }

    /** Runs {@code agent} once, at {@code tick}. */
    public void scheduleOnce(long tick, int ordering, Steppable agent) {
        queue.add(newEvent(tick, ordering, 0, agent));
    }

    /** Runs {@code agent} once, at the tick after the current one. */
    public void scheduleOnce(Steppable agent, int ordering) {
        scheduleOnce(time + 1, ordering, agent);
    }

    /** Runs {@code agent} at {@code firstTick} and every {@code interval} ticks after, until stopped. */
    public Stoppable scheduleRepeating(long firstTick, int ordering, long interval, Steppable agent) {
        if (interval < 1) {
            throw new IllegalArgumentException("a repeating event needs an interval of at least 1 tick, not " + interval);
        }
        Event event = newEvent(firstTick, ordering, interval, agent);
        queue.add(event);
        return event;
    }

    /** Runs {@code agent} every tick from the next one on, until stopped. */
    public Stoppable scheduleRepeating(Steppable agent, int ordering) {
        return scheduleRepeating(time + 1, ordering, 1, agent);
    }

    /**
     * Runs every event of the next scheduled tick, in (ordering, shuffled) order; or, when an agent
     * {@link #pause}d the tick in progress, goes on with it: that agent steps again, then the rest.
     *
     * @return false if there was nothing to run
     */
    public boolean step(SimState state) {
        if (pausedAt >= 0) {
            int from = pausedAt;
            pausedAt = -1;
            runDue(state, from, false);
            return true;
        }
        Event first = queue.peek();
        if (first == null) {
            return false;
        }
        time = first.tick;
        due.clear();
        while (!queue.isEmpty() && queue.peek().tick == time) {
            due.add(queue.poll());
        }
        shuffleWithinOrderings();
        runDue(state, 0, true);
        return true;
    }

    /**
     * Asked by the agent stepping now: the tick stops after its step, and the next {@link #step}
     * steps it again and goes on from there. An agent that waits for an answer computed elsewhere
     * (a controller answering several runs in one message) pauses its run's tick until the answer
     * is in; the tick then runs exactly as it would have without the pause.
     */
    public void pause() {
        pauseAsked = true;
    }

    /** Whether a tick is in progress, paused by one of its agents. */
    public boolean isPaused() {
        return pausedAt >= 0;
    }

    /** Steps the due events from index {@code from}; the first is re-queued only when it has not been already. */
    private void runDue(SimState state, int from, boolean queueFirst) {
        long started = generation;
        for (int i = from; i < due.size(); i++) {
            Event event = due.get(i);
            if (event.stopped) {
                continue;
            }
            if (event.interval > 0 && (queueFirst || i > from)) {
                event.tick += event.interval;
                queue.add(event);
            }
            event.agent.step(state);
            if (generation != started) {
                break;
            }
            if (pauseAsked) {
                pauseAsked = false;
                pausedAt = i;
                return;
            }
        }
        due.clear();
    }

    /** Removes every event, including the rest of a tick in progress. Time is kept. */
    public void clear() {
        queue.clear();
        due.clear();
        pausedAt = -1;
        pauseAsked = false;
        generation++;
    }

    private Event newEvent(long tick, int ordering, long interval, Steppable agent) {
        if (agent == null) {
            throw new IllegalArgumentException("cannot schedule a null agent");
        }
        if (tick <= time) {
            throw new IllegalArgumentException("cannot schedule an event at tick " + tick
                    + ": the schedule is at tick " + time + ", so the earliest tick is " + (time + 1));
        }
        return new Event(this, tick, ordering, nextSequence++, interval, agent);
    }

    /** Fisher–Yates shuffle of each run of equal ordering in {@code due}, which arrives sorted. */
    private void shuffleWithinOrderings() {
        int start = 0;
        while (start < due.size()) {
            int ordering = due.get(start).ordering;
            int end = start + 1;
            while (end < due.size() && due.get(end).ordering == ordering) {
                end++;
            }
            for (int i = end - 1; i > start; i--) {
                int j = start + shuffle.nextInt(i - start + 1);
                Event swap = due.get(i);
                due.set(i, due.get(j));
                due.set(j, swap);
            }
            start = end;
        }
    }

    /**
     * A scheduled agent; mutable only inside the schedule, where it is re-queued each interval.
     * Static, with its schedule in a field of its own: an inner class's hidden reference to its
     * outer object is final, and a checkpoint copies events.
     */
    private static final class Event implements Stoppable, Comparable<Event> {
        private Schedule schedule;
        private long tick;
        private int ordering;
        private long sequence;
        private long interval;
        private Steppable agent;
        private boolean stopped;

        private Event(Schedule schedule, long tick, int ordering, long sequence, long interval, Steppable agent) {
            this.schedule = schedule;
            this.tick = tick;
            this.ordering = ordering;
            this.sequence = sequence;
            this.interval = interval;
            this.agent = agent;
        }

        /** By tick, then ordering, then the order of scheduling (written out: it runs a dozen times a tick). */
        @Override
        public int compareTo(Event o) {
            if (tick != o.tick) {
                return tick < o.tick ? -1 : 1;
            }
            if (ordering != o.ordering) {
                return ordering < o.ordering ? -1 : 1;
            }
            return Long.compare(sequence, o.sequence);
        }

        @Override
        public void stop() {
            if (!stopped) {
                stopped = true;
                schedule.queue.remove(this);
            }
        }
    }
}
