package sitcov.estimate;

import java.util.Set;
import sitcov.world.DrawSite;

/**
 * An estimate's plan. Per replication: {@code mcMaps} maps drawn from the generator (plain Monte
 * Carlo); then {@code ceStages} cross-entropy stages of {@code ceMaps} maps, the first under the
 * generator, each refitting the proposal over {@code sites}; then {@code isMaps} maps drawn under
 * the last proposal, whose weighted failures are the importance-sampling estimate. Replications are
 * independent (each its own proposal), the unit a shard takes.
 *
 * @param controller    the controller under test, as {@code --controller} names it
 * @param eliteQuantile the share of a stage's runs, least score first, that make its elite while
 *                      fewer of them fail
 * @param smoothing     the weight of the refitted proposal against the current one
 * @param defensive     the generator's share mixed into every proposal
 */
public record EstimateConfig(String name, long masterSeed, String controller, int replications, int mcMaps,
                             int ceStages, int ceMaps, int isMaps, double eliteQuantile, double smoothing,
                             double defensive, Set<DrawSite> sites) {
    public static final int MAX_MAPS = 1_000_000;
    public static final int MAX_REPLICATIONS = 10_000;
    public static final int MAX_STAGES = 50;

    public EstimateConfig {
        sites = Set.copyOf(sites);
    }

    /** Whether the plan estimates by importance sampling (else plain Monte Carlo only). */
    public boolean importanceSampling() {
        return isMaps > 0;
    }

    /** The seed of map {@code index} of {@code stage} in {@code replication}; also its internal seed. */
    public long seed(int replication, String stage, int index) {
        return sitcov.engine.RandomStreams.mix(masterSeed, "estimate:replication-" + replication + ":" + stage + ":" + index);
    }
}
