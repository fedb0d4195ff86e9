package sitcov.cli;

import java.io.IOException;
import java.io.Reader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Properties;
import java.util.Set;
import sitcov.coverage.GridDefinition;
import sitcov.drivers.Drivers;
import sitcov.experiment.AnalysisPlan;
import sitcov.experiment.BudgetKind;
import sitcov.experiment.CampaignConfig;
import sitcov.experiment.CampaignTarget;
import sitcov.experiment.ExperimentConfig;
import sitcov.faults.FaultSet;
import sitcov.judge.FaultyRuns;
import sitcov.judge.Requirement;
import sitcov.judge.Variant;
import sitcov.judge.VariantList;
import sitcov.protocol.ControllerChoice;
import sitcov.results.IoReason;

/**
 * An experiment preset: a properties file in {@code experiments/}, named by file or by name. A
 * preset with {@code sweep=} budgets is an effort sweep; one with {@code protocol=campaign} a
 * falsification campaign ({@code campaign}, and {@code config} null); otherwise it is a comparison.
 */
record Preset(Path file, ExperimentConfig config, CampaignConfig campaign) {
    /** The keys only the suites' protocol takes, and those only a campaign takes. */
    private static final List<String> SUITES_ONLY = List.of("candidates", "replications", "budget", "sweep");
    private static final List<String> CAMPAIGN_ONLY = List.of("trials", "tick_budget");

    private static final Set<String> KEYS = keys();

    private static Set<String> keys() {
        Set<String> keys = new java.util.TreeSet<>(List.of("name", "master_seed", "candidates", "replications", "faults",
                "budget", "faulty_runs", "grid", "description", "sweep", "drivers", "candidate_limit", "controller",
                "protocol", "trials", "tick_budget", "variants", "requirements"));
        keys.addAll(AnalysisPlan.keys());
        return Set.copyOf(keys);
    }

    static Path locate(String nameOrFile) throws UsageException {
        Path direct = Path.of(nameOrFile);
        if (Files.isRegularFile(direct)) {
            return direct;
        }
        Path named = Path.of("experiments", nameOrFile + ".properties");
        if (Files.isRegularFile(named)) {
            return named;
        }
        throw new UsageException("run: no preset '" + nameOrFile + "': neither a file nor experiments/" + nameOrFile
                + ".properties; the presets are the .properties files in experiments/ (e.g. smoke, paper-rq1).");
    }

    static Preset read(Path file, Long masterSeedOverride, Drivers drivers) throws UsageException {
        return read(file, masterSeedOverride, null, java.util.Map.of(), drivers);
    }

    /**
     * The preset, with its master seed and number of replications replaced where an override is given,
     * and its keys {@code keys} (from the command line: {@code controller}, {@code variants}) replacing its own.
     */
    static Preset read(Path file, Long masterSeedOverride, Integer replicationsOverride, java.util.Map<String, String> keys,
                       Drivers drivers) throws UsageException {
        Properties p = new Properties();
        String text;
        try {
            text = Files.readString(file, StandardCharsets.UTF_8);
            p.load(new java.io.StringReader(text));
        } catch (java.nio.charset.CharacterCodingException e) {
            throw new UsageException("run: " + file + " is not UTF-8 text; a preset is a properties file such as"
                    + " experiments/smoke.properties.");
        } catch (IOException e) {
            throw new UsageException("run: cannot read the preset " + file + ": " + sitcov.results.IoReason.of(e, file) + ".");
        } catch (IllegalArgumentException e) {
            throw new UsageException("run: cannot read the preset " + file + ": " + e.getMessage() + ".");
        }
        duplicateKeys(text, file);
        if (keys.containsKey("variants")) {
            p.remove("faults"); // the variants given replace the preset's, whichever key named them
        }
        keys.forEach(p::setProperty);
        String protocol = p.getProperty("protocol", "suites").strip();
        if (protocol.equals("campaign")) {
            if (replicationsOverride != null) {
                p.setProperty("trials", replicationsOverride.toString());
            }
            return new Preset(file, null, campaign(p, file, masterSeedOverride, drivers));
        }
        if (!protocol.equals("suites")) {
            throw new UsageException("run: " + file + ": protocol=" + protocol + " is not a protocol; use protocol=suites"
                    + " (test suites compared, the default) or protocol=campaign (falsification campaigns).");
        }
        if (p.containsKey("requirements")) {
            throw new UsageException("run: " + file + ": requirements= chooses the reference's own requirements that a"
                    + " falsification campaign seeks to violate; add protocol=campaign with variants=none (and trials=,"
                    + " tick_budget=), or remove requirements= (the suites count the own failures of variants=none as"
                    + " they are).");
        }
        for (String key : CAMPAIGN_ONLY) {
            if (p.containsKey(key)) {
                throw new UsageException("run: " + file + ": " + key + "= belongs to a falsification campaign; add"
                        + " protocol=campaign, or remove " + key + "= (the suites' budget is candidates= and budget=).");
            }
        }
        if (replicationsOverride != null) {
            p.setProperty("replications", replicationsOverride.toString());
        }
        return new Preset(file, config(p, file, masterSeedOverride, drivers), null);
    }

    /** A campaign (experiments/README.md, "Campaigns: falsifying one version"): the suites' own keys are refused, not ignored. */
    private static CampaignConfig campaign(Properties p, Path file, Long masterSeedOverride, Drivers known)
            throws UsageException {
        for (String key : p.stringPropertyNames()) {
            if (!KEYS.contains(key)) {
                throw new UsageException("run: " + file + ": unknown key '" + key + "'; the keys are "
                        + KEYS.stream().sorted().toList() + ".");
            }
            if (SUITES_ONLY.contains(key) || AnalysisPlan.keys().contains(key)) {
                throw new UsageException("run: " + file + ": " + key + "= belongs to the suites' protocol; a campaign"
                        + " (protocol=campaign) is sized by trials= and tick_budget=: remove " + key + "=.");
            }
        }
        String name = name(p, file);
        try {
            long seed = masterSeedOverride != null ? masterSeedOverride : Long.parseLong(required(p, "master_seed", file));
            if (!p.containsKey("tick_budget")) {
                throw new UsageException("run: " + file + ": protocol=campaign needs tick_budget=T, the simulated ticks one"
                        + " trial of one driver may spend; add it (e.g. tick_budget=200000).");
            }
            long ticks = count(file, "tick_budget", p.getProperty("tick_budget"), Integer.MAX_VALUE);
            int trials = count(file, "trials", required(p, "trials", file), ExperimentConfig.MAX_REPLICATIONS);
            String controller = Controllers.check(p.getProperty("controller", ExperimentConfig.BUILTIN).strip());
            List<CampaignTarget> targets = targets(p, file, controller);
            String limit = p.getProperty("candidate_limit");
            int candidateLimit = limit == null ? CampaignConfig.DEFAULT_CANDIDATE_LIMIT
                    : count(file, "candidate_limit", limit, ExperimentConfig.MAX_CANDIDATES);
            FaultyRuns faultyRuns = FaultyRuns.ofKey(p.getProperty("faulty_runs", FaultyRuns.UNTIL_VERDICT.key()).strip());
            String gridFile = p.getProperty("grid");
            GridDefinition grid = gridFile == null ? GridDefinition.paper() : GridDefinition.read(Path.of(gridFile.strip()));
            return new CampaignConfig(name, seed, targets, drivers(p, file, known), trials, ticks,
                    candidateLimit, grid, faultyRuns, controller);
        } catch (IOException e) {
            throw new UsageException("run: " + file + ": cannot read its grid: " + sitcov.results.IoReason.of(e) + ".");
        } catch (NumberFormatException e) {
            throw new UsageException("run: " + file + ": master_seed= needs a whole number, not '"
                    + p.getProperty("master_seed", "").strip() + "'.");
        } catch (IllegalArgumentException e) {
            throw new UsageException("run: " + file + ": " + e.getMessage() + ".");
        }
    }

    /**
     * What a campaign falsifies: each of the reference's variants, or with {@code variants=none} each of its own
     * requirements, those {@code requirements=} names or every one that applies to its controller.
     */
    private static List<CampaignTarget> targets(Properties p, Path file, String controller) throws UsageException {
        List<Variant> variants = variants(p, file, controller);
        if (!variants.isEmpty()) {
            if (p.containsKey("requirements")) {
                throw new UsageException("run: " + file + ": requirements= chooses the reference's own requirements, which a"
                        + " campaign falsifies with variants=none; this one falsifies " + variants.size() + " variant"
                        + (variants.size() == 1 ? "" : "s") + ": set variants=none, or remove requirements=.");
            }
            return CampaignConfig.ofVariants(variants);
        }
        if (!p.containsKey("requirements")) {
            ControllerChoice choice = ControllerChoice.parse(controller);
            boolean inProcessBuiltin = choice instanceof ControllerChoice.Builtin || choice instanceof ControllerChoice.Planted;
            return CampaignConfig.ofRequirements(Requirement.defaults(!inProcessBuiltin));
        }
        List<Requirement> chosen = new ArrayList<>();
        for (String part : p.getProperty("requirements").split(",", -1)) {
            Requirement r;
            try {
                r = Requirement.ofKey(part);
            } catch (IllegalArgumentException e) {
                throw new UsageException("run: " + file + ": requirements=: " + e.getMessage() + " (separated by commas).");
            }
            if (chosen.contains(r)) {
                throw new UsageException("run: " + file + ": requirements= names " + r.key() + " twice; name it once.");
            }
            chosen.add(r);
        }
        return CampaignConfig.ofRequirements(chosen);
    }

    private static String name(Properties p, Path file) throws UsageException {
        String name = p.getProperty("name", file.getFileName().toString().replaceFirst("\\.properties$", "")).strip();
        if (!name.matches("[A-Za-z0-9][A-Za-z0-9._-]*")) {
            throw new UsageException("run: " + file + ": name=" + name + " must be letters, digits, '.', '_' and '-'"
                    + " (it names the results folder).");
        }
        return name;
    }

    private static ExperimentConfig config(Properties p, Path file, Long masterSeedOverride, Drivers known)
            throws UsageException {
        for (String key : p.stringPropertyNames()) {
            if (!KEYS.contains(key)) {
                throw new UsageException("run: " + file + ": unknown key '" + key + "'; the keys are "
                        + KEYS.stream().sorted().toList() + ".");
            }
        }
        String name = p.getProperty("name", file.getFileName().toString().replaceFirst("\\.properties$", "")).strip();
        if (!name.matches("[A-Za-z0-9][A-Za-z0-9._-]*")) {
            throw new UsageException("run: " + file + ": name=" + name + " must be letters, digits, '.', '_' and '-'"
                    + " (it names the results folder).");
        }
        String field = "master_seed";
        try {
            long seed = masterSeedOverride != null ? masterSeedOverride : Long.parseLong(required(p, "master_seed", file));
            int candidates = count(file, "candidates", required(p, "candidates", file), ExperimentConfig.MAX_CANDIDATES);
            int replications = count(file, "replications", p.getProperty("replications", "1"),
                    ExperimentConfig.MAX_REPLICATIONS);
            String controller = Controllers.check(p.getProperty("controller", ExperimentConfig.BUILTIN).strip());
            List<Variant> variants = variants(p, file, controller);
            field = "budget";
            BudgetKind budget = BudgetKind.ofKey(p.getProperty("budget", "ticks").strip());
            field = "drivers";
            List<String> drivers = drivers(p, file, known);
            List<Integer> sweep = sweep(p, file, replications);
            String limit = p.getProperty("candidate_limit");
            int candidateLimit = limit == null ? ExperimentConfig.defaultCandidateLimit(candidates, sweep)
                    : count(file, "candidate_limit", limit, ExperimentConfig.MAX_CANDIDATE_LIMIT);
            field = "faulty_runs";
            FaultyRuns faultyRuns = FaultyRuns.ofKey(p.getProperty("faulty_runs", FaultyRuns.UNTIL_VERDICT.key()).strip());
            field = "grid";
            String gridFile = p.getProperty("grid");
            GridDefinition grid = gridFile == null ? GridDefinition.paper() : GridDefinition.read(Path.of(gridFile.strip()));
            field = "analysis";
            AnalysisPlan analysis = AnalysisPlan.read(p::getProperty, drivers);
            if (variants.isEmpty() && !p.containsKey(AnalysisPlan.PRIMARY_MEASURE)) {
                // with no variant to find, the question is the reference's own failures
                analysis = analysis.withPrimary(sitcov.experiment.Measure.DISTINCT_OWN_FAILURES);
            }
            return new ExperimentConfig(name, seed, candidates, replications, variants, budget, grid, drivers, sweep,
                    candidateLimit, faultyRuns, analysis, controller);
        } catch (IOException e) {
            throw new UsageException("run: " + file + ": cannot read its grid: " + sitcov.results.IoReason.of(e) + ".");
        } catch (NumberFormatException e) {
            throw new UsageException("run: " + file + ": " + field + "= needs a whole number, not '"
                    + p.getProperty(field, "").strip() + "'.");
        } catch (IllegalArgumentException e) {
            throw new UsageException("run: " + file + ": " + e.getMessage() + ".");
        }
    }

    /**
     * The reference's variants: {@code variants=} as given, or {@code faults=} (the builtin car's seeded
     * faults, one variant each); without either, a builtin reference's {@code PAPER} faults and no
     * variants for any other reference.
     */
    private static List<Variant> variants(Properties p, Path file, String controller) throws UsageException {
        if (p.containsKey("variants") && p.containsKey("faults")) {
            throw new UsageException("run: " + file + ": give the variants once: variants= lists them all (builtin:F for"
                    + " a seeded fault), faults= is its shorthand for the builtin car's; remove one of them.");
        }
        if (p.containsKey("variants")) {
            try {
                return VariantList.parse(p.getProperty("variants"));
            } catch (IllegalArgumentException e) {
                throw new UsageException("run: " + file + ": variants: " + e.getMessage() + ".");
            }
        }
        if (!p.containsKey("faults") && !controller.equals(ExperimentConfig.BUILTIN)) {
            return List.of();
        }
        var faults = FaultSet.parse(p.getProperty("faults", "PAPER"));
        if (faults.isEmpty()) {
            throw new UsageException("run: " + file + ": faults=" + p.getProperty("faults").strip() + " leaves no fault"
                    + " to find; name at least one, e.g. faults=PAPER, or variants=none to seek the reference's own"
                    + " failures.");
        }
        return ExperimentConfig.seeded(faults);
    }

    /** Properties keep the last of two lines with one key; a preset with a key twice is more likely a mistake. */
    private static void duplicateKeys(String text, Path file) throws UsageException {
        Set<String> seen = new java.util.HashSet<>();
        boolean continued = false;
        int n = 0;
        for (String raw : text.split("\\R", -1)) {
            n++;
            String line = raw.stripLeading();
            boolean wasContinued = continued;
            continued = !line.startsWith("#") && !line.startsWith("!") && raw.matches(".*(?<!\\\\)(\\\\\\\\)*\\\\$");
            if (wasContinued || line.isEmpty() || line.startsWith("#") || line.startsWith("!")) {
                continue;
            }
            String key = line.split("[=:\\s]", 2)[0];
            if (!seen.add(key)) {
                throw new UsageException("run: " + file + ":" + n + ": the key '" + key + "' is given twice; keep one.");
            }
        }
    }

    private static List<String> drivers(Properties p, Path file, Drivers known) throws UsageException {
        List<String> drivers = new ArrayList<>();
        for (String part : p.getProperty("drivers", String.join(",", ExperimentConfig.PAPER_DRIVERS)).split(",")) {
            String d = part.strip();
            if (!known.has(d)) {
                throw new UsageException("run: " + file + ": drivers= names an unknown driver '" + d + "'; the drivers are "
                        + String.join(", ", known.names()) + ".");
            }
            drivers.add(d);
        }
        return drivers;
    }

    /**
     * A count of the preset from 1 to {@code max}, by the rule of the command line's counts
     * ({@link Options#count}): the limit is named when it is passed, before anything is planned.
     */
    private static int count(Path file, String key, String text, int max) throws UsageException {
        try {
            long v = Long.parseLong(text.strip());
            if (v >= 1 && v <= max) {
                return (int) v;
            }
        } catch (NumberFormatException e) {
            // reported below
        }
        throw new UsageException("run: " + file + ": " + key + "= needs a whole number from 1 to " + max + ", not '"
                + text.strip() + "'.");
    }

    /**
     * The candidate budgets of an effort sweep ({@code sweep=200,500,...}), or an empty list for a
     * comparison; every budget is a count of candidates, and the map sets of all budgets together are
     * held to the limit of replications.
     */
    private static List<Integer> sweep(Properties p, Path file, int replications) throws UsageException {
        String text = p.getProperty("sweep");
        if (text == null) {
            return List.of();
        }
        List<Integer> budgets = new ArrayList<>();
        for (String part : text.split(",")) {
            if (!part.strip().matches("[0-9]+")) {
                throw new UsageException("run: " + file + ": sweep= needs positive candidate counts such as"
                        + " 200,500,1000, not '" + part.strip() + "'.");
            }
            budgets.add(count(file, "sweep", part, ExperimentConfig.MAX_CANDIDATES));
        }
        if ((long) budgets.size() * replications > ExperimentConfig.MAX_REPLICATIONS) {
            throw new UsageException("run: " + file + ": sweep= has " + budgets.size() + " budgets of " + replications
                    + " map sets each (replications=), " + (long) budgets.size() * replications + " in all; the limit is "
                    + ExperimentConfig.MAX_REPLICATIONS + ": lower replications= (or --replications) or the budgets.");
        }
        return budgets;
    }

    private static String required(Properties p, String key, Path file) throws UsageException {
        String v = p.getProperty(key);
        if (v == null) {
            throw new UsageException("run: " + file + " lacks '" + key + "='; add it.");
        }
        return v.strip();
    }
}
