package sitcov.estimate;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.function.Consumer;
import java.util.function.Supplier;
import sitcov.oracle.RunResult;
import sitcov.world.MapGenerator;
import sitcov.world.Tilt;
import sitcov.world.TracedMap;
import sitcov.world.WorldMap;

/**
 * Runs the stages of an estimate's replications ({@link EstimateConfig}). The maps of a stage run
 * on all threads, each a pure function of its seed and proposal, so the samples are the same on any
 * number of threads.
 */
public final class EstimateRunner implements AutoCloseable {
    /** Runs one map to its end; each thread gets its own from the supplier. */
    public interface Judge {
        RunResult run(WorldMap map, long internalSeed);
    }

    /** What one replication drew and ran. */
    public record Replication(List<Sample> samples, List<ProposalRow> proposals) {
    }

    private final EstimateConfig config;
    private final ThreadLocal<Judge> judges;
    private final ExecutorService pool;
    private final Consumer<String> progress;

    public EstimateRunner(EstimateConfig config, Supplier<Judge> judge, int threads, Consumer<String> progress) {
        this.config = config;
        this.judges = ThreadLocal.withInitial(judge);
        this.pool = Executors.newFixedThreadPool(threads, r -> {
            Thread t = new Thread(r, "estimate");
            t.setDaemon(true);
            return t;
        });
        this.progress = progress;
    }

    public Replication run(int replication) {
        List<Sample> samples = new ArrayList<>();
        List<ProposalRow> proposals = new ArrayList<>();
        if (config.mcMaps() > 0) {
            samples.addAll(stage(replication, "mc", Tilt.NOMINAL, config.mcMaps()));
        }
        if (config.importanceSampling()) {
            Tilt tilt = Tilt.NOMINAL;
            double level = Double.NaN;
            int elite = 0;
            for (int t = 1; t <= config.ceStages(); t++) {
                String stage = "ce-" + t;
                proposals.add(new ProposalRow(replication, stage, level, elite, tilt));
                List<Sample> drawn = stage(replication, stage, tilt, config.ceMaps());
                samples.addAll(drawn);
                CrossEntropy.Fit fit = CrossEntropy.refit(tilt, drawn, config.sites(), config.eliteQuantile(),
                        config.smoothing(), config.defensive());
                tilt = fit.tilt();
                level = fit.level();
                elite = fit.elite();
                progress.accept("replication " + replication + " " + stage + ": elite of " + elite + " at score "
                        + String.format(java.util.Locale.ROOT, "%.4f", level));
            }
            proposals.add(new ProposalRow(replication, "is", level, elite, tilt));
            samples.addAll(stage(replication, "is", tilt, config.isMaps()));
        }
        return new Replication(samples, proposals);
    }

    private List<Sample> stage(int replication, String stage, Tilt tilt, int maps) {
        List<Future<Sample>> futures = new ArrayList<>();
        for (int i = 0; i < maps; i++) {
            int index = i;
            futures.add(pool.submit(() -> {
                long seed = config.seed(replication, stage, index);
                TracedMap drawn = MapGenerator.generate(seed, tilt);
                RunResult result = judges.get().run(drawn.map(), seed);
                return Sample.of(replication, stage, index, seed, drawn.trace(), result);
            }));
        }
        List<Sample> samples = new ArrayList<>();
        try {
            for (Future<Sample> f : futures) {
                samples.add(f.get());
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted", e);
        } catch (ExecutionException e) {
            throw e.getCause() instanceof RuntimeException r ? r : new IllegalStateException(e.getCause());
        }
        long failed = samples.stream().filter(s -> !s.failures().isEmpty()).count();
        progress.accept("replication " + replication + " " + stage + ": " + maps + " maps, " + failed + " failed");
        return samples;
    }

    @Override
    public void close() {
        pool.shutdownNow();
    }
}
