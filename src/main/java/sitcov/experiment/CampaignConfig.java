package sitcov.experiment;

import java.util.List;
import java.util.Locale;
import java.util.Objects;
import sitcov.coverage.GridDefinition;
import sitcov.judge.FaultyRuns;
import sitcov.judge.Variant;

/**
 * A falsification campaign (experiments/README.md, "Campaigns: falsifying one version"): for each of {@code variants}
 * on its own, {@code trials} independent trials per driver, each driver of a trial spending at most
 * {@code tickBudget} simulated ticks and stopping at its first map that finds the variant. The campaign
 * of one variant is an ordinary experiment ({@link #trialsOf}) kept in a sub-folder ({@link #folderOf}).
 */
public record CampaignConfig(String name, long masterSeed, List<Variant> variants, List<String> drivers, int trials,
                             long tickBudget, int candidateLimit, GridDefinition grid, FaultyRuns faultyRuns,
                             String controller) {
    /** Candidates one driver may draw in one trial unless the preset says otherwise: a safety limit only. */
    public static final int DEFAULT_CANDIDATE_LIMIT = 100_000;

    public CampaignConfig {
        if (variants.isEmpty()) {
            throw new IllegalArgumentException("a campaign falsifies at least one variant");
        }
        if (trials < 1 || tickBudget < 1 || candidateLimit < 1) {
            throw new IllegalArgumentException("a campaign needs at least one trial, one tick and one candidate");
        }
        if (drivers.isEmpty() || drivers.stream().distinct().count() != drivers.size()) {
            throw new IllegalArgumentException("a campaign names one or more drivers, each once, got " + drivers);
        }
        // in id order: the order of every per-variant row and panel
        variants = variants.stream().sorted(java.util.Comparator.comparingInt(Variant::id)).toList();
        if (variants.stream().map(Variant::id).distinct().count() != variants.size()) {
            throw new IllegalArgumentException("a campaign's variants have distinct ids, got " + variants);
        }
        drivers = List.copyOf(drivers);
        Objects.requireNonNull(grid, "grid");
        Objects.requireNonNull(faultyRuns, "faultyRuns");
        Objects.requireNonNull(controller, "controller");
    }

    /** The experiment that runs the trials of {@code variant}: its own master seed ({@link SeedPlan#campaignSeed}). */
    public ExperimentConfig trialsOf(Variant variant) {
        if (!variants.contains(variant)) {
            throw new IllegalArgumentException("variant " + variant.id() + " is not one of the campaign's");
        }
        return new ExperimentConfig(name + "-" + folderOf(variant), SeedPlan.campaignSeed(masterSeed, variant.id()),
                candidateLimit, trials, List.of(variant), BudgetKind.FIXED_TICKS, grid, drivers, List.of(), candidateLimit,
                faultyRuns, AnalysisPlan.defaults(drivers), controller, tickBudget);
    }

    /** The sub-folder of the campaign's results folder that holds the trials of {@code variant}. */
    public static String folderOf(Variant variant) {
        return String.format(Locale.ROOT, variant instanceof Variant.Seeded ? "fault-%02d" : "variant-%02d", variant.id());
    }

    /** Whether every variant is a seeded fault of the builtin car (the folder then names them by {@code faults=}). */
    public boolean onlySeeded() {
        return variants.stream().allMatch(v -> v instanceof Variant.Seeded);
    }
}
