package sitcov.cli;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Properties;
import java.util.Set;
import sitcov.coverage.GridDefinition;
import sitcov.drivers.Drivers;
import sitcov.experiment.AnalysisPlan;
import sitcov.experiment.BudgetKind;
import sitcov.experiment.ExperimentConfig;
import sitcov.judge.FaultyRuns;
import sitcov.judge.Variant;
import sitcov.judge.VariantList;

/**
 * {@code versions}: a controller's variants (its next version, a build with a planted bug) against
 * the reference controller on N maps, by the differential oracle (experiments/controllers/README.md, "Versions
 * compared"). A
 * thin command over an ordinary experiment: one driver ({@code random}: every map drawn is run),
 * one replication, the reference and its variants; it writes an ordinary results folder, whose
 * verdict gives each variant against the reference.
 */
final class VersionsCommand implements Command {
    static final int MAX_MAPS = 1_000_000;
    private static final String DRIVER = "random";
    private static final Set<String> KEYS = Set.of("name", "description", "reference", "variants", "maps", "master_seed");

    @Override
    public String name() {
        return "versions";
    }

    @Override
    public String synopsis() {
        return "PRESET | --reference CONTROLLER --variants VARIANT[;VARIANT…]  [--maps N] [--seed S] [--threads T] [--fork on|off] [--record failures|all] [--out DIR]";
    }

    @Override
    public String summary() {
        return "compare controller versions map by map: where does a variant fail that the reference did not?";
    }

    @Override
    public int run(List<String> args, PrintStream out, PrintStream err) throws UsageException {
        Options options = Options.parse(name(), args, Set.of("--reference", "--variants", "--maps", "--seed", "--threads",
                "--fork", "--out", "--record"), Set.of());
        int threads = options.threads(err);
        ExperimentConfig config = config(options);
        return new RunCommand(Drivers.standard()).forking(options.forks()).start(config, options, "versions " + config.name(),
                threads, out, err);
    }

    /** The experiment the options name: N maps drawn from the seed's stream, every one run, the reference and its variants. */
    private static ExperimentConfig config(Options options) throws UsageException {
        Properties p = new Properties();
        String name = "versions";
        if (options.positional().size() == 1) {
            Path file = presetFile(options.positional().get(0));
            try {
                p.load(new java.io.StringReader(Files.readString(file, StandardCharsets.UTF_8)));
            } catch (IOException | IllegalArgumentException e) {
                throw new UsageException("versions: cannot read the preset " + file + ": " + e.getMessage() + ".");
            }
            for (String key : p.stringPropertyNames()) {
                if (!KEYS.contains(key)) {
                    throw new UsageException("versions: " + file + ": unknown key '" + key + "'; the keys are "
                            + KEYS.stream().sorted().toList() + ".");
                }
            }
            name = p.getProperty("name", file.getFileName().toString().replaceFirst("\\.properties$", "")).strip();
        } else if (!options.positional().isEmpty()) {
            throw new UsageException("versions: name one preset, or give --reference and --variants.");
        }
        options.value("--reference").ifPresent(v -> p.setProperty("reference", v));
        options.value("--variants").ifPresent(v -> p.setProperty("variants", v));
        String reference = p.getProperty("reference", "").strip();
        String variants = p.getProperty("variants", "").strip();
        if (reference.isEmpty() || variants.isEmpty()) {
            throw new UsageException("versions: name the reference controller and its variants, e.g. --reference builtin"
                    + " --variants 'builtin:16;builtin:17', or a preset with reference= and variants=.");
        }
        if (VariantList.namesNone(variants)) {
            // 'none' or only separators: a comparison with nothing to compare is not one
            throw new UsageException("versions: --variants '" + variants + "' names no variant; name at least one,"
                    + " e.g. --variants 'builtin:16', separated by ';'.");
        }
        List<Variant> list;
        try {
            list = VariantList.parse(variants);
        } catch (IllegalArgumentException e) {
            throw new UsageException("versions: variants: " + e.getMessage() + ".");
        }
        for (Variant v : list) {
            if (v instanceof Variant.Controller c) {
                Controllers.check(c.spec());
            }
        }
        Controllers.check(reference);
        int maps = options.count("--maps", 1, MAX_MAPS).orElse(countOf(p.getProperty("maps", "100")));
        long seed = options.seed("--seed").orElse(seedOf(p.getProperty("master_seed", "1")));
        List<String> drivers = List.of(DRIVER);
        try {
            return new ExperimentConfig(name, seed, maps, 1, list, BudgetKind.TICKS, GridDefinition.paper(), drivers,
                    List.of(), maps, FaultyRuns.UNTIL_VERDICT, AnalysisPlan.defaults(drivers), reference);
        } catch (IllegalArgumentException e) {
            throw new UsageException("versions: " + e.getMessage() + ".");
        }
    }

    private static Path presetFile(String named) throws UsageException {
        Path shipped = Path.of("experiments", "controllers", named + ".properties");
        Path file = Files.isRegularFile(shipped) ? shipped : Path.of(named);
        if (!Files.isRegularFile(file)) {
            throw new UsageException("versions: no preset '" + named + "': neither a file nor " + shipped
                    + "; the shipped one is byo-controller, or give --reference and --variants.");
        }
        return file;
    }

    private static int countOf(String text) throws UsageException {
        try {
            int n = Integer.parseInt(text.strip());
            if (n >= 1 && n <= MAX_MAPS) {
                return n;
            }
        } catch (NumberFormatException e) {
            // said below
        }
        throw new UsageException("versions: maps= needs a whole number from 1 to " + MAX_MAPS + ", not '" + text.strip() + "'.");
    }

    private static long seedOf(String text) throws UsageException {
        try {
            return Long.parseLong(text.strip());
        } catch (NumberFormatException e) {
            throw new UsageException("versions: master_seed= needs a whole number, not '" + text.strip() + "'.");
        }
    }
}
