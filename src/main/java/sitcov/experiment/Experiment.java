package sitcov.experiment;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.function.IntConsumer;
import java.util.function.LongSupplier;

/**
 * Runs the replications of an experiment, in parallel on {@code threads} threads. Each replication
 * is self-contained and seeded from the master seed, and results come back in replication order,
 * so under the ticks budget the results do not depend on the thread count.
 */
public final class Experiment {
    private Experiment() {
    }

    public static List<ReplicationResult> run(ExperimentConfig config, int threads, LongSupplier nanoClock,
                                              IntConsumer replicationsDone) {
        ExecutorService pool = Executors.newFixedThreadPool(Math.max(1, Math.min(threads, config.replications())));
        try {
            List<Future<ReplicationResult>> futures = new ArrayList<>();
            for (int r = 0; r < config.replications(); r++) {
                int replication = r;
                futures.add(pool.submit(() -> new Replication(config, replication, nanoClock).run()));
            }
            List<ReplicationResult> results = new ArrayList<>();
            for (Future<ReplicationResult> f : futures) {
                results.add(f.get());
                replicationsDone.accept(results.size());
            }
            return results;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("experiment interrupted", e);
        } catch (ExecutionException e) {
            throw new IllegalStateException("experiment failed: " + e.getCause(), e.getCause());
        } finally {
            pool.shutdownNow();
        }
    }
}
