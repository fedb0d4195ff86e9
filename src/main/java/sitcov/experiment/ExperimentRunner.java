package sitcov.experiment;

import java.io.UncheckedIOException;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.function.LongSupplier;
import sitcov.control.ControllerFactory;
import sitcov.control.ControllerSource;
import sitcov.judge.Variant;

/**
 * Runs an experiment's replications (those of one shard) in parallel and tells the listeners what
 * happens. Each replication's lead/follow protocol is its {@link ReplicationPlan}; its later drivers
 * run beside its first under the ticks budget, after it under the wall-clock budget. Each replication is seeded from the master seed
 * alone, so under the ticks budget what is judged never depends on the thread count.
 */
public final class ExperimentRunner {
    private final ExperimentConfig config;
    private final DriverFactory drivers;
    private final Shard shard;
    private final Journal journal;
    private final int threads;
    private final LongSupplier nanoClock;
    private final List<ExperimentListener> listeners;
    private final List<Variant> variants;
    private final ControllerSource controllers;
    private final java.util.Map<Integer, ControllerSource> variantControllers;
    private volatile boolean recordAll;
    private volatile boolean halted;

    /** A runner whose worker threads take the reference's controllers from {@code controllers} (which the caller closes). */
    public ExperimentRunner(ExperimentConfig config, DriverFactory drivers, Shard shard, Journal journal, int threads,
                            LongSupplier nanoClock, List<ExperimentListener> listeners, ControllerSource controllers) {
        this(config, drivers, shard, journal, threads, nanoClock, listeners, controllers, java.util.Map.of());
    }

    /**
     * A runner whose worker threads take the reference's controllers from {@code controllers} and those of
     * each variant that is a controller of its own from {@code variantControllers}, by variant id (the caller
     * closes them all).
     */
    public ExperimentRunner(ExperimentConfig config, DriverFactory drivers, Shard shard, Journal journal, int threads,
                            LongSupplier nanoClock, List<ExperimentListener> listeners, ControllerSource controllers,
                            java.util.Map<Integer, ControllerSource> variantControllers) {
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
        this.variants = config.variants();
        this.controllers = controllers;
        this.variantControllers = java.util.Map.copyOf(variantControllers);
    }

    /** Where each worker thread gets its controller. */
    ControllerSource controllers() {
        return controllers;
    }

    /** Records every run, passing ones too ({@code --record all}), not only the failures and findings. */
    public ExperimentRunner recordingAll(boolean all) {
        this.recordAll = all;
        return this;
    }

    boolean recordsAll() {
        return recordAll;
    }

    /** The replications this run does: the plan's, or the shard's share of it. */
    public List<PlannedReplication> replications() {
        return config.plan().stream().filter(p -> shard.includes(p.index())).toList();
    }

    /**
     * Runs every replication not yet finished; returns false if {@link #halt()} stopped it first
     * (nothing is emitted after a halt, so what listeners wrote is what a kill would leave).
     *
     * @throws UncheckedIOException as a listener threw it, when it could not write
     * @throws IllegalStateException when anything else failed
     */
    public boolean run() {
        List<PlannedReplication> todo = replications();
        emit(new ExperimentEvent.Started(config, shard, todo, threads, journal.size()));
        int drivers = config.drivers().size();
        // under the ticks budget a replication's later drivers run beside its first, which changes no
        // result and keeps every core busy however few replications a shard has; under the wall-clock
        // budget they run after it, as in the paper, each with a core of its own
        boolean beside = config.budget() != BudgetKind.WALL_CLOCK;
        ExecutorService pool = Executors.newFixedThreadPool(Math.max(1, Math.min(threads, todo.size() * (beside ? drivers : 1))));
        try {
            List<Future<?>> futures = new ArrayList<>();
            // a replication's drivers are queued one after another: its first is always taken up before the
            // later ones that wait on it, so even one thread runs them all, in the preset's order
            for (PlannedReplication p : todo) {
                ReplicationPlan plan = new ReplicationPlan(p, config);
                if (beside) {
                    for (int d = 0; d < drivers; d++) {
                        int driver = d;
                        futures.add(pool.submit(() -> runDriver(plan, driver)));
                    }
                } else {
                    futures.add(pool.submit(() -> {
                        for (int d = 0; d < drivers; d++) {
                            runDriver(plan, d);
                        }
                    }));
                }
            }
            for (Future<?> f : futures) {
                f.get();
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            halted = true;
        } catch (ExecutionException e) {
            if (e.getCause() instanceof UncheckedIOException io) {
                // a listener could not write (a full disk, a deleted folder): its own message says what and where
                halted = true;
                throw io;
            }
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

    /** One driver's share of a replication, with the budget and the shared maps its plan gives it. */
    private void runDriver(ReplicationPlan plan, int d) {
        Driver driver = drivers.create(config.drivers().get(d));
        DriverSession session = new DriverSession(this, plan, d, journal, driver);
        Journal.Finished done;
        try {
            driver.drive(session);
            done = session.finish();
        } catch (RuntimeException | Error e) {
            plan.failed(d);
            throw e;
        }
        plan.finished(d, done);
        emit(new ExperimentEvent.DriverDone(done.spend(), d, session.wasFinishedBefore(), done.driverNanos()));
        if (plan.countOff()) {
            emit(new ExperimentEvent.ReplicationDone(plan.replication().index()));
        }
    }

    ExperimentConfig config() {
        return config;
    }

    /** This worker thread's controller of a variant that is a controller of its own. */
    ControllerFactory variantController(Variant.Controller variant) {
        ControllerSource source = variantControllers.get(variant.id());
        if (source == null) {
            throw new IllegalStateException("no controller was started for variant " + variant.id() + " (" + variant.spec() + ")");
        }
        return source.forThisThread();
    }

    List<Variant> variants() {
        return variants;
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
