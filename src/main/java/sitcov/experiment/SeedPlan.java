package sitcov.experiment;

import java.util.random.RandomGenerator;
import sitcov.engine.RandomStreams;
import sitcov.judge.Requirement;

/**
 * Where every seed of an experiment comes from; nothing else derives one. From the master seed M:
 * <ul>
 * <li>replication r of a comparison draws its candidates' external seeds from stream
 *   {@code candidates} of {@code M} derived by {@code replication-r}; every driver of the
 *   replication reads that same sequence from its start, so replications are paired;</li>
 * <li>map set s at candidate budget b of a sweep uses {@code sweep-b-set-s} in place of
 *   {@code replication-r} (distinct for every b and s, unlike the former {@code b*1000+s});</li>
 * <li>a generated map's internal seed is {@code mix(M, "internal-seed:" + external seed)}, so
 *   every driver runs a shared map identically; a built situation's is
 *   {@code mix(M, "internal-seed:situation:" + name)};</li>
 * <li>the map itself, and everything random in a run, come from the external and internal seeds'
 *   own named streams ({@link sitcov.world.MapGenerator}, {@link sitcov.engine.SimState});</li>
 * <li>the campaign of fault f (experiments/README.md, "Campaigns: falsifying one version") is an experiment of its
 *   own whose master seed is {@code mix(M, "campaign-fault-" + f)}, every rule above applied to it,
 *   so the trials of different faults read different candidates; the campaign of the reference's own
 *   requirement r (experiments/README.md, "Requirement campaigns: where your controller itself fails") likewise
 *   {@code mix(M, "campaign-requirement-" + r)}, r its key;</li>
 * <li>a driver's own choices (a search's: which situation to edit, how) come from stream
 *   {@code choices:DRIVER} of {@code M} derived by the replication's label;</li>
 * <li>the analysis of the results (bootstrap resamples, permutations) draws from stream
 *   {@code purpose} of {@code M} derived by {@code analysis}, so its intervals and p-values
 *   are reproduced with the results.</li>
 * </ul>
 */
public final class SeedPlan {
    private SeedPlan() {
    }

    public static String replicationLabel(int replication) {
        return "replication-" + replication;
    }

    public static String sweepLabel(int budget, int set) {
        return "sweep-" + budget + "-set-" + set;
    }

    /** The candidate external seeds of the replication labelled {@code label}, in order. */
    public static RandomGenerator candidates(long masterSeed, String label) {
        return new RandomStreams(masterSeed).derive(label).stream("candidates");
    }

    /** The candidate stream of replication {@code replication} of a comparison. */
    public static RandomGenerator candidates(long masterSeed, int replication) {
        return candidates(masterSeed, replicationLabel(replication));
    }

    /** The stream of a driver's own choices in the replication (or map set) labelled {@code label}. */
    public static RandomGenerator choices(long masterSeed, String label, String driver) {
        return new RandomStreams(masterSeed).derive(label).stream("choices:" + driver);
    }

    /** The randomness of one analysis of the results, e.g. {@code "bootstrap"} or {@code "cell-permutations"}. */
    public static RandomGenerator analysis(long masterSeed, String purpose) {
        return new RandomStreams(masterSeed).derive("analysis").stream(purpose);
    }

    /** The master seed of the campaign for variant {@code variantId} (a seeded fault's id): its trials' seeds derive from it. */
    public static long campaignSeed(long masterSeed, int variantId) {
        return RandomStreams.mix(masterSeed, "campaign-fault-" + variantId);
    }

    /** The master seed of the campaign of the reference's own {@code requirement}: its trials' seeds derive from it. */
    public static long campaignSeed(long masterSeed, Requirement requirement) {
        return RandomStreams.mix(masterSeed, "campaign-requirement-" + requirement.key());
    }

    /** The internal seed a map runs with: fixed by the master seed and the map, whichever driver runs it. */
    public static long internalSeed(long masterSeed, MapId map) {
        if (map instanceof MapId.Seeded s) {
            return RandomStreams.mix(masterSeed, "internal-seed:" + s.externalSeed());
        }
        return RandomStreams.mix(masterSeed, "internal-seed:situation:" + ((MapId.Situation) map).name());
    }
}
