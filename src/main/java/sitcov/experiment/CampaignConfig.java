package sitcov.experiment;

import java.util.EnumSet;
import java.util.List;
import java.util.Locale;
import java.util.Objects;
import java.util.Set;
import sitcov.coverage.GridDefinition;
import sitcov.faults.Fault;
import sitcov.judge.FaultyRuns;

/**
 * A falsification campaign (README, "Campaigns: falsifying one version"): for each of {@code faults}
 * on its own, {@code trials} independent trials per driver, each driver of a trial spending at most
 * {@code tickBudget} simulated ticks and stopping at its first map that finds the fault. The campaign of
 * one fault is an ordinary experiment ({@link #trialsOf}) kept in a sub-folder ({@link #folderOf}).
 */
public record CampaignConfig(String name, long masterSeed, List<Fault> faults, List<String> drivers, int trials,
                             long tickBudget, int candidateLimit, GridDefinition grid, FaultyRuns faultyRuns,
                             String controller) {
    /** Candidates one driver may draw in one trial unless the preset says otherwise: a safety limit only. */
    public static final int DEFAULT_CANDIDATE_LIMIT = 100_000;

    public CampaignConfig {
        if (faults.isEmpty()) {
            throw new IllegalArgumentException("a campaign falsifies at least one fault");
        }
        if (trials < 1 || tickBudget < 1 || candidateLimit < 1) {
            throw new IllegalArgumentException("a campaign needs at least one trial, one tick and one candidate");
        }
        if (drivers.isEmpty() || drivers.stream().distinct().count() != drivers.size()) {
            throw new IllegalArgumentException("a campaign names one or more drivers, each once, got " + drivers);
        }
        // in id order, each once: the order of every per-fault row and panel
        faults = List.copyOf(EnumSet.copyOf(faults));
        drivers = List.copyOf(drivers);
        Objects.requireNonNull(grid, "grid");
        Objects.requireNonNull(faultyRuns, "faultyRuns");
        Objects.requireNonNull(controller, "controller");
    }

    /** The experiment that runs the trials of {@code fault}: its own master seed ({@link SeedPlan#campaignSeed}). */
    public ExperimentConfig trialsOf(Fault fault) {
        if (!faults.contains(fault)) {
            throw new IllegalArgumentException("fault " + fault.id() + " is not one of the campaign's");
        }
        return new ExperimentConfig(name + "-" + folderOf(fault), SeedPlan.campaignSeed(masterSeed, fault.id()),
                candidateLimit, trials, ExperimentConfig.seeded(Set.of(fault)), BudgetKind.FIXED_TICKS, grid, drivers, List.of(), candidateLimit,
                faultyRuns, AnalysisPlan.defaults(drivers), controller, tickBudget);
    }

    /** The sub-folder of the campaign's results folder that holds the trials of {@code fault}. */
    public static String folderOf(Fault fault) {
        return String.format(Locale.ROOT, "fault-%02d", fault.id());
    }
}
