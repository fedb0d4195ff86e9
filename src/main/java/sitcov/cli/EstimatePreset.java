package sitcov.cli;

import java.io.IOException;
import java.io.Reader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.EnumSet;
import java.util.Properties;
import java.util.Set;
import sitcov.estimate.EstimateConfig;
import sitcov.world.DrawSite;

/** A preset with {@code protocol=estimate} (experiments/estimate.md): its keys read into an {@link EstimateConfig}. */
final class EstimatePreset {
    private static final Set<String> KEYS = Set.of("protocol", "description", "master_seed", "controller", "replications",
            "mc_maps", "ce_stages", "ce_maps", "is_maps", "elite_quantile", "smoothing", "defensive", "sites");

    private EstimatePreset() {
    }

    /** Whether the preset file says {@code protocol=estimate}; a file that cannot be read is left to the suites' reader, which says why. */
    static boolean isEstimate(Path file) {
        try {
            return "estimate".equals(properties(file).getProperty("protocol", "").strip());
        } catch (UsageException e) {
            return false;
        }
    }

    static EstimateConfig read(Path file, Long seed, Integer replications, String controller) throws UsageException {
        Properties p = properties(file);
        for (String key : p.stringPropertyNames()) {
            if (!KEYS.contains(key)) {
                throw new UsageException("estimate: " + file + ": " + key + "= is not a key of an estimate; the keys are "
                        + String.join(", ", new java.util.TreeSet<>(KEYS)) + " (experiments/estimate.md).");
            }
        }
        String name = file.getFileName().toString().replaceFirst("\\.properties$", "");
        int isMaps = count(p, file, "is_maps", 1000, 0);
        int mcMaps = count(p, file, "mc_maps", 0, 0);
        if (isMaps == 0 && mcMaps == 0) {
            throw new UsageException("estimate: " + file + ": both mc_maps and is_maps are 0, so nothing would run; set"
                    + " mc_maps=N for plain Monte Carlo or is_maps=N for importance sampling.");
        }
        return new EstimateConfig(name, seed != null ? seed : masterSeed(p, file),
                controller != null ? controller : p.getProperty("controller", "builtin").strip(),
                replications != null ? replications : count(p, file, "replications", 1, 1), mcMaps,
                count(p, file, "ce_stages", 3, isMaps > 0 ? 1 : 0), count(p, file, "ce_maps", 500, isMaps > 0 ? 1 : 0),
                isMaps, share(p, file, "elite_quantile", 0.1), share(p, file, "smoothing", 0.7),
                share(p, file, "defensive", 0.1), sites(p, file));
    }

    private static long masterSeed(Properties p, Path file) throws UsageException {
        String v = p.getProperty("master_seed", "1");
        try {
            return Long.parseLong(v.strip());
        } catch (NumberFormatException e) {
            throw new UsageException("estimate: " + file + ": master_seed=" + v + " is not a whole number (64-bit); fix it.");
        }
    }

    private static int count(Properties p, Path file, String key, int otherwise, long least) throws UsageException {
        String v = p.getProperty(key);
        if (v == null) {
            return otherwise;
        }
        try {
            long n = Long.parseLong(v.strip());
            if (n < least || n > EstimateConfig.MAX_MAPS) {
                throw new NumberFormatException();
            }
            return Math.toIntExact(n);
        } catch (NumberFormatException | ArithmeticException e) {
            throw new UsageException("estimate: " + file + ": " + key + "=" + v + " is not a whole number from " + least
                    + " to " + EstimateConfig.MAX_MAPS + "; fix it.");
        }
    }

    private static double share(Properties p, Path file, String key, double otherwise) throws UsageException {
        String v = p.getProperty(key);
        if (v == null) {
            return otherwise;
        }
        try {
            double x = Double.parseDouble(v.strip());
            if (x > 0 && x <= 1) {
                return x;
            }
        } catch (NumberFormatException e) {
            // the message below
        }
        throw new UsageException("estimate: " + file + ": " + key + "=" + v + " is not a share above 0 and at most 1; fix it.");
    }

    private static Set<DrawSite> sites(Properties p, Path file) throws UsageException {
        Set<DrawSite> sites = EnumSet.noneOf(DrawSite.class);
        for (String key : p.getProperty("sites", "junctions,parked,moving").split(",")) {
            DrawSite s = DrawSite.byKey(key.strip());
            if (s == null) {
                StringBuilder known = new StringBuilder();
                for (DrawSite d : DrawSite.values()) {
                    known.append(known.isEmpty() ? "" : ", ").append(d.key());
                }
                throw new UsageException("estimate: " + file + ": sites= names '" + key.strip() + "', not a draw of the"
                        + " generator; the sites are " + known + ".");
            }
            sites.add(s);
        }
        return sites;
    }

    private static Properties properties(Path file) throws UsageException {
        Properties p = new Properties();
        try (Reader r = Files.newBufferedReader(file, StandardCharsets.UTF_8)) {
            p.load(r);
        } catch (IOException e) {
            throw new UsageException("estimate: cannot read the preset " + file + ": " + e.getMessage() + ".");
        }
        return p;
    }
}
