package sitcov.experiment;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
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
        List<Callable<ReplicationResult>> tasks = new ArrayList<>();
        for (int r = 0; r < config.replications(); r++) {
            int replication = r;
            tasks.add(() -> new Replication(config, replication, nanoClock).run());
        }
        return InOrder.run(tasks, threads, replicationsDone, "experiment " + config.name());
    }
}
