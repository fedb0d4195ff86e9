package sitcov.experiment;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.function.LongSupplier;
import sitcov.faults.Fault;

/**
 * Runs an experiment's replications (those of one shard) in parallel and tells the listeners what
 * happens. Within a replication the drivers run in the preset's order: the first draws its
 * candidates, each later one gets the same budget. Each replication is seeded from the master seed
 * alone, so under the ticks budget what is judged never depends on the thread count.
 */
public final class ExperimentRunner {
    private final ExperimentConfig config;
    private final Drivers drivers;
    private final Shard shard;
    private final Journal journal;
    private final int threads;
    private final LongSupplier nanoClock;
    private final List<ExperimentListener> listeners;
    private final List<Fault> faults;
    private volatile boolean halted;

    public ExperimentRunner(ExperimentConfig config, Drivers drivers, Shard shard, Journal journal, int threads,
                            LongSupplier nanoClock, List<ExperimentListener> listeners) {
        for (String d : config.drivers()) {
            drivers.create(d);
        }
        this.config = config;
        this.drivers = drivers;
        this.shard = shard;
        this.journal = journal;
        this.threads = Math.max(1, threads);
        this.nanoClock = nanoClock;
        this.listeners = List.copyOf(listeners);
        this.faults = config.faultList();
    }

    /** The replications this run does: the plan's, or the shard's share of it. */
    public List<PlannedReplication> replications() {
        return config.plan().stream().filter(p -> shard.includes(p.index())).toList();
    }

    /**
     * Runs every replication not yet finished; returns false if {@link #halt()} stopped it first
     * (nothing is emitted after a halt, so what listeners wrote is what a kill would leave).
     */
    public boolean run() {
        List<PlannedReplication> todo = replications();
        emit(new ExperimentEvent.Started(config, shard, todo, threads, journal.size()));
        ExecutorService pool = Executors.newFixedThreadPool(Math.max(1, Math.min(threads, todo.size())));
        try {
            List<Future<?>> futures = new ArrayList<>();
            for (PlannedReplication p : todo) {
                futures.add(pool.submit(() -> runReplication(p)));
            }
            for (Future<?> f : futures) {
                f.get();
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            halted = true;
        } catch (ExecutionException e) {
            if (!(e.getCause() instanceof Halted)) {
                halted = true;
                throw new IllegalStateException("experiment " + config.name() + " failed: " + e.getCause(), e.getCause());
            }
        } finally {
            pool.shutdownNow();
            awaitQuietly(pool);
        }
        if (halted) {
            return false;
        }
        emit(new ExperimentEvent.Ended(config, shard));
        return true;
    }

    /** Stops the run as a kill would: no event is delivered after this call returns. */
    public void halt() {
        halted = true;
    }

    private void runReplication(PlannedReplication p) {
        DriverSpend first = null;
        long firstNanos = 0;
        // drivers of a replication read the same candidates: a map two of them run is judged once
        Map<MapId, DriverSession.SharedMap> shared = new HashMap<>();
        for (int d = 0; d < config.drivers().size(); d++) {
            String name = config.drivers().get(d);
            Budget budget = d == 0 ? Budget.candidates(p.candidates())
                    : Budget.after(config.budget(), first, firstNanos, config.candidateLimit());
            Driver driver = drivers.create(name);
            DriverSession session = new DriverSession(this, p, name, d, budget, journal, driver, shared);
            driver.drive(session);
            Journal.Finished done = session.finish();
            emit(new ExperimentEvent.DriverDone(done.spend(), d, session.wasFinishedBefore(), done.driverNanos()));
            if (d == 0) {
                first = done.spend();
                firstNanos = done.driverNanos();
            }
        }
        emit(new ExperimentEvent.ReplicationDone(p.index()));
    }

    ExperimentConfig config() {
        return config;
    }

    List<Fault> faults() {
        return faults;
    }

    long nanoTime() {
        return nanoClock.getAsLong();
    }

    void checkHalt() {
        if (halted) {
            throw new Halted();
        }
    }

    /** Delivers one event to every listener, one event at a time. */
    void emit(ExperimentEvent event) {
        synchronized (listeners) {
            checkHalt();
            for (ExperimentListener l : listeners) {
                l.on(event);
            }
        }
    }

    private static void awaitQuietly(ExecutorService pool) {
        try {
            while (!pool.awaitTermination(1, TimeUnit.SECONDS)) {
                // a worker finishes the map it is judging, then stops at its next check
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    /** Unwinds a worker after {@link #halt()}. */
    private static final class Halted extends RuntimeException {
        private static final long serialVersionUID = 1L;

        Halted() {
            super("halted", null, false, false);
        }
    }
}
