package sitcov.estimate;

import java.util.ArrayList;
import java.util.EnumSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.stream.Collectors;
import sitcov.results.ManifestChecks;
import sitcov.world.DrawSite;

/**
 * manifest.properties of an estimate's folder: its plan, the sitcov version, the shard, the digests of the samples
 * and proposals written with it, and whether it is complete, one {@code key=value} a line in a fixed order (no date:
 * a folder's bytes depend only on its plan). {@code protocol=estimate} tells it from an experiment's manifest.
 */
public final class EstimateManifest {
    public static final String FILE = "manifest.properties";
    public static final String PROTOCOL = "estimate";
    /** The digests of samples.csv and proposals.csv: what {@code merge} reads is what the estimate wrote. */
    public static final String SAMPLES_SHA256 = "samples_sha256";
    public static final String PROPOSALS_SHA256 = "proposals_sha256";

    private EstimateManifest() {
    }

    /**
     * {@code digests}: the samples' and the proposals' SHA-256, written with the checks of every line
     * (experiments/README.md, "Guarded against hand edits"); empty for a folder whose files are unattested.
     */
    public static List<String> lines(EstimateConfig c, String version, int shardK, int shardN, boolean complete,
                                     Optional<List<String>> digests) {
        List<String> l = new ArrayList<>();
        l.add("protocol=" + PROTOCOL);
        l.add("name=" + c.name());
        l.add("master_seed=" + c.masterSeed());
        l.add("controller=" + c.controller());
        l.add("replications=" + c.replications());
        l.add("mc_maps=" + c.mcMaps());
        l.add("ce_stages=" + c.ceStages());
        l.add("ce_maps=" + c.ceMaps());
        l.add("is_maps=" + c.isMaps());
        l.add("elite_quantile=" + c.eliteQuantile());
        l.add("smoothing=" + c.smoothing());
        l.add("defensive=" + c.defensive());
        l.add("sites=" + sites(c.sites()));
        l.add("version=" + version);
        l.add("shard=" + shardK + "/" + shardN);
        if (digests.isEmpty()) {
            l.add("complete=" + complete);
            return l;
        }
        l.add(SAMPLES_SHA256 + "=" + digests.get().get(0));
        l.add(PROPOSALS_SHA256 + "=" + digests.get().get(1));
        // attested: its own lines checked too, so the plan the estimates are made under cannot be edited unnoticed
        return ManifestChecks.inOrder(l, complete);
    }

    /** The sites in {@link DrawSite} order, by key. */
    public static String sites(Set<DrawSite> sites) {
        return EnumSet.copyOf(sites.isEmpty() ? EnumSet.noneOf(DrawSite.class) : sites).stream().map(DrawSite::key)
                .collect(Collectors.joining(","));
    }

    /** The manifest's keys and values, in file order. */
    public static Map<String, String> parse(List<String> lines) {
        Map<String, String> m = new LinkedHashMap<>();
        for (String line : lines) {
            int eq = line.indexOf('=');
            if (eq > 0) {
                m.put(line.substring(0, eq), line.substring(eq + 1));
            }
        }
        return m;
    }

    /**
     * The plan a manifest holds.
     *
     * @throws IllegalArgumentException when a key is missing or malformed
     */
    public static EstimateConfig config(Map<String, String> m) {
        try {
            Set<DrawSite> sites = EnumSet.noneOf(DrawSite.class);
            for (String key : m.getOrDefault("sites", "").split(",")) {
                if (!key.isBlank()) {
                    sites.add(java.util.Objects.requireNonNull(DrawSite.byKey(key.strip()), "site " + key));
                }
            }
            return new EstimateConfig(get(m, "name"), Long.parseLong(get(m, "master_seed")), get(m, "controller"),
                    Integer.parseInt(get(m, "replications")), Integer.parseInt(get(m, "mc_maps")),
                    Integer.parseInt(get(m, "ce_stages")), Integer.parseInt(get(m, "ce_maps")),
                    Integer.parseInt(get(m, "is_maps")), Double.parseDouble(get(m, "elite_quantile")),
                    Double.parseDouble(get(m, "smoothing")), Double.parseDouble(get(m, "defensive")), sites);
        } catch (NumberFormatException | NullPointerException e) {
            throw new IllegalArgumentException("the manifest is malformed (" + e.getMessage() + ")");
        }
    }

    private static String get(Map<String, String> m, String key) {
        String v = m.get(key);
        if (v == null) {
            throw new IllegalArgumentException("the manifest lacks " + key + "=");
        }
        return v;
    }
}
