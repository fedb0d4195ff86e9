package sitcov.experiment;

import java.util.Comparator;
import java.util.List;
import java.util.Objects;
import java.util.Optional;
import sitcov.coverage.GridDefinition;
import sitcov.judge.FaultyRuns;
import sitcov.judge.Requirement;
import sitcov.judge.Variant;

/**
 * A falsification campaign (experiments/README.md, "Campaigns: falsifying one version"): for each of {@code targets}
 * on its own — the reference's variants, or its own requirements — {@code trials} independent trials per driver,
 * each driver of a trial spending at most {@code tickBudget} simulated ticks and stopping at its first map that
 * falsifies the target. The campaign of one target is an ordinary experiment ({@link #trialsOf}) kept in a
 * sub-folder ({@link CampaignTarget#folder}).
 */
public record CampaignConfig(String name, long masterSeed, List<CampaignTarget> targets, List<String> drivers, int trials,
                             long tickBudget, int candidateLimit, GridDefinition grid, FaultyRuns faultyRuns,
                             String controller) {
    /** Candidates one driver may draw in one trial unless the preset says otherwise: a safety limit only. */
    public static final int DEFAULT_CANDIDATE_LIMIT = 100_000;

    public CampaignConfig {
        if (targets.isEmpty()) {
            throw new IllegalArgumentException("a campaign falsifies at least one variant or requirement");
        }
        if (targets.stream().map(Object::getClass).distinct().count() != 1) {
            throw new IllegalArgumentException("a campaign falsifies the reference's variants or its own requirements,"
                    + " not both, got " + targets);
        }
        if (trials < 1 || tickBudget < 1 || candidateLimit < 1) {
            throw new IllegalArgumentException("a campaign needs at least one trial, one tick and one candidate");
        }
        if (drivers.isEmpty() || drivers.stream().distinct().count() != drivers.size()) {
            throw new IllegalArgumentException("a campaign names one or more drivers, each once, got " + drivers);
        }
        // variants in id order, requirements in theirs: the order of every per-target row and panel
        targets = targets.stream().sorted(Comparator.comparingInt(CampaignTarget::order)).toList();
        if (targets.stream().map(CampaignTarget::folder).distinct().count() != targets.size()) {
            throw new IllegalArgumentException("a campaign's targets are distinct, got " + targets);
        }
        drivers = List.copyOf(drivers);
        Objects.requireNonNull(grid, "grid");
        Objects.requireNonNull(faultyRuns, "faultyRuns");
        Objects.requireNonNull(controller, "controller");
    }

    /** Each of {@code variants} a target of its own. */
    public static List<CampaignTarget> ofVariants(List<? extends Variant> variants) {
        return variants.stream().<CampaignTarget>map(CampaignTarget.OfVariant::new).toList();
    }

    /** Each of {@code requirements} a target of its own. */
    public static List<CampaignTarget> ofRequirements(List<Requirement> requirements) {
        return requirements.stream().<CampaignTarget>map(CampaignTarget.OfRequirement::new).toList();
    }

    /** The experiment that runs the trials of {@code target}: its own master seed ({@link CampaignTarget#seed}). */
    public ExperimentConfig trialsOf(CampaignTarget target) {
        if (!targets.contains(target)) {
            throw new IllegalArgumentException(target.title() + " is not one of the campaign's");
        }
        List<Variant> variants = target instanceof CampaignTarget.OfVariant v ? List.of(v.variant()) : List.of();
        Optional<Requirement> requirement = target instanceof CampaignTarget.OfRequirement r
                ? Optional.of(r.requirement()) : Optional.empty();
        return new ExperimentConfig(name + "-" + target.folder(), target.seed(masterSeed), candidateLimit, trials, variants,
                BudgetKind.FIXED_TICKS, grid, drivers, List.of(), candidateLimit, faultyRuns, AnalysisPlan.defaults(drivers),
                controller, tickBudget, requirement);
    }

    /** Whether it falsifies the reference's own requirements (else its variants). */
    public boolean onRequirements() {
        return targets.get(0) instanceof CampaignTarget.OfRequirement;
    }

    /** The variants it falsifies, in order; none in a requirement campaign. */
    public List<Variant> variants() {
        return targets.stream().filter(t -> t instanceof CampaignTarget.OfVariant)
                .map(t -> ((CampaignTarget.OfVariant) t).variant()).toList();
    }

    /** The requirements it falsifies, in order; none in a campaign of variants. */
    public List<Requirement> requirements() {
        return targets.stream().filter(t -> t instanceof CampaignTarget.OfRequirement)
                .map(t -> ((CampaignTarget.OfRequirement) t).requirement()).toList();
    }

    /** What one target is called in sentences: {@code fault} or {@code requirement}. */
    public String noun() {
        return onRequirements() ? "requirement" : "fault";
    }

    /** Whether every target is a seeded fault of the builtin car (the folder then names them by {@code faults=}). */
    public boolean onlySeeded() {
        return !onRequirements() && variants().stream().allMatch(v -> v instanceof Variant.Seeded);
    }
}
