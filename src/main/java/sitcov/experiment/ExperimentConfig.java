package sitcov.experiment;

import java.util.ArrayList;
import java.util.EnumSet;
import java.util.List;
import java.util.Objects;
import java.util.Optional;
import java.util.Set;
import sitcov.coverage.GridDefinition;
import sitcov.faults.Fault;
import sitcov.judge.FaultyRuns;
import sitcov.judge.Requirement;
import sitcov.judge.Variant;

/**
 * One experiment. A comparison: per replication, the first of {@code drivers} draws
 * {@code candidates} candidates; each later driver gets the same budget of the given kind (and never
 * draws more than {@code candidateLimit}). A sweep ({@code sweep} not empty): the same, once per
 * candidate budget of the sweep and map set, with {@code replications} map sets per budget.
 * {@code analysis} declares how a comparison's results are judged. A campaign's trials of one fault
 * (budget {@code fixed-ticks}): every driver gets {@code tickBudget} ticks per replication (0 for
 * every other budget), with {@code candidates} only its safety limit; they falsify its one variant, or,
 * with no variant, the reference's own {@code requirement} (empty for every other experiment).
 */
public record ExperimentConfig(String name, long masterSeed, int candidates, int replications, List<Variant> variants,
                               BudgetKind budget, GridDefinition grid, List<String> drivers, List<Integer> sweep,
                               int candidateLimit, FaultyRuns faultyRuns, AnalysisPlan analysis, String controller,
                               long tickBudget, Optional<Requirement> requirement) {
    /** The controller an experiment tests unless its preset names another. */
    public static final String BUILTIN = "builtin";

    public static final List<String> PAPER_DRIVERS = List.of("coverage-filter", "random");
    /**
     * Replications, or a sweep's map sets over all its budgets: far beyond any sound experiment (Arcuri &amp;
     * Briand ask for 1000), and few enough that the plan of them all fits in memory at once.
     */
    public static final int MAX_REPLICATIONS = 1_000_000;
    /** Candidates a first driver draws in a replication (a sweep budget too): 500 times the paper's 20 000. */
    public static final int MAX_CANDIDATES = 10_000_000;
    /** A later driver's candidate limit: ten times the most candidates, as the default limit is. */
    public static final int MAX_CANDIDATE_LIMIT = 10 * MAX_CANDIDATES;

    public ExperimentConfig {
        if (candidates < 1 || replications < 1) {
            throw new IllegalArgumentException("an experiment needs at least one candidate and one replication");
        }
        if (candidates > MAX_CANDIDATES || sweep.stream().anyMatch(b -> b > MAX_CANDIDATES)
                || candidateLimit > MAX_CANDIDATE_LIMIT) {
            throw new IllegalArgumentException("an experiment draws at most " + MAX_CANDIDATES + " candidates a replication"
                    + " (candidate_limit at most " + MAX_CANDIDATE_LIMIT + ")");
        }
        if ((long) replications * Math.max(1, sweep.size()) > MAX_REPLICATIONS) {
            throw new IllegalArgumentException("an experiment has at most " + MAX_REPLICATIONS + " replications (map sets"
                    + " over all budgets of a sweep)");
        }
        if (drivers.isEmpty() || drivers.stream().distinct().count() != drivers.size()) {
            throw new IllegalArgumentException("an experiment names one or more drivers, each once, got " + drivers);
        }
        if (sweep.stream().anyMatch(b -> b < 1)) {
            throw new IllegalArgumentException("sweep budgets are positive candidate counts, got " + sweep);
        }
        int largest = sweep.stream().mapToInt(Integer::intValue).max().orElse(candidates);
        if (candidateLimit < largest) {
            throw new IllegalArgumentException("candidate_limit " + candidateLimit + " is below the first driver's "
                    + largest + " candidates");
        }
        Objects.requireNonNull(faultyRuns, "faultyRuns");
        Objects.requireNonNull(analysis, "analysis");
        if (!drivers.containsAll(analysis.primaryDrivers())) {
            throw new IllegalArgumentException("the primary question's drivers " + analysis.primaryDrivers()
                    + " are not among the drivers " + drivers);
        }
        Objects.requireNonNull(controller, "controller");
        if ((budget == BudgetKind.FIXED_TICKS) != (tickBudget > 0)) {
            throw new IllegalArgumentException("a tick budget goes with the fixed-ticks budget of a campaign, and only"
                    + " with it (got budget " + budget.key() + ", tick budget " + tickBudget + ")");
        }
        Objects.requireNonNull(requirement, "requirement");
        int targets = variants.size() + (requirement.isPresent() ? 1 : 0);
        if (budget == BudgetKind.FIXED_TICKS && (targets != 1 || !sweep.isEmpty())) {
            throw new IllegalArgumentException("a campaign's trials falsify one variant or one requirement and sweep"
                    + " nothing, got " + variants.size() + " variants, requirement " + requirement + " and sweep " + sweep);
        }
        if (budget != BudgetKind.FIXED_TICKS && requirement.isPresent()) {
            throw new IllegalArgumentException("only a campaign's trials falsify a requirement");
        }
        variants = List.copyOf(variants);
        if (variants.stream().map(Variant::id).distinct().count() != variants.size()) {
            throw new IllegalArgumentException("an experiment's variants have distinct ids, got " + variants);
        }
        drivers = List.copyOf(drivers);
        sweep = List.copyOf(sweep);
    }

    /** Anything but a requirement campaign's trials. */
    public ExperimentConfig(String name, long masterSeed, int candidates, int replications, List<Variant> variants,
                            BudgetKind budget, GridDefinition grid, List<String> drivers, List<Integer> sweep,
                            int candidateLimit, FaultyRuns faultyRuns, AnalysisPlan analysis, String controller,
                            long tickBudget) {
        this(name, masterSeed, candidates, replications, variants, budget, grid, drivers, sweep, candidateLimit, faultyRuns,
                analysis, controller, tickBudget, Optional.empty());
    }

    /** Any budget but a campaign's fixed ticks. */
    public ExperimentConfig(String name, long masterSeed, int candidates, int replications, List<Variant> variants,
                            BudgetKind budget, GridDefinition grid, List<String> drivers, List<Integer> sweep,
                            int candidateLimit, FaultyRuns faultyRuns, AnalysisPlan analysis, String controller) {
        this(name, masterSeed, candidates, replications, variants, budget, grid, drivers, sweep, candidateLimit, faultyRuns,
                analysis, controller, 0);
    }

    /** Testing the builtin car. */
    public ExperimentConfig(String name, long masterSeed, int candidates, int replications, Set<Fault> faults,
                            BudgetKind budget, GridDefinition grid, List<String> drivers, List<Integer> sweep,
                            int candidateLimit, FaultyRuns faultyRuns, AnalysisPlan analysis) {
        this(name, masterSeed, candidates, replications, seeded(faults), budget, grid, drivers, sweep, candidateLimit,
                faultyRuns, analysis, BUILTIN);
    }

    /** The same experiment testing the controller {@code spec} names ({@code builtin} or {@code exec:COMMAND ARGS…}). */
    public ExperimentConfig withController(String spec) {
        return new ExperimentConfig(name, masterSeed, candidates, replications, variants, budget, grid, drivers, sweep,
                candidateLimit, faultyRuns, analysis, spec, tickBudget, requirement);
    }

    /** The same experiment judging {@code others} as the reference's variants. */
    public ExperimentConfig withVariants(List<Variant> others) {
        return new ExperimentConfig(name, masterSeed, candidates, replications, others, budget, grid, drivers, sweep,
                candidateLimit, faultyRuns, analysis, controller, tickBudget, requirement);
    }

    /** The default analysis: distinct faults found, the first driver against the second, default margins. */
    public ExperimentConfig(String name, long masterSeed, int candidates, int replications, Set<Fault> faults,
                            BudgetKind budget, GridDefinition grid, List<String> drivers, List<Integer> sweep,
                            int candidateLimit, FaultyRuns faultyRuns) {
        this(name, masterSeed, candidates, replications, faults, budget, grid, drivers, sweep, candidateLimit, faultyRuns,
                AnalysisPlan.defaults(drivers));
    }

    /** The paper's two drivers, no sweep, a candidate limit ten times the first driver's candidates, faulty runs until their verdict. */
    public ExperimentConfig(String name, long masterSeed, int candidates, int replications, Set<Fault> faults,
                            BudgetKind budget, GridDefinition grid) {
        this(name, masterSeed, candidates, replications, faults, budget, grid, PAPER_DRIVERS, List.of(),
                defaultCandidateLimit(candidates, List.of()), FaultyRuns.UNTIL_VERDICT);
    }

    /** Ten times the largest candidate budget of the first driver: later drivers that run few maps still stop. */
    public static int defaultCandidateLimit(int candidates, List<Integer> sweep) {
        long largest = sweep.stream().mapToInt(Integer::intValue).max().orElse(candidates);
        return (int) Math.min(Integer.MAX_VALUE, largest * 10L);
    }

    /** What a campaign's trials falsify: the reference's requirement, else its one variant. */
    public CampaignTarget target() {
        if (budget != BudgetKind.FIXED_TICKS) {
            throw new IllegalStateException(name + " is not a campaign's trials");
        }
        return requirement.<CampaignTarget>map(CampaignTarget.OfRequirement::new)
                .orElseGet(() -> new CampaignTarget.OfVariant(variants.get(0)));
    }

    /** The builtin car's seeded faults, each a variant, in id order: the order of every per-fault column. */
    public static List<Variant> seeded(Set<Fault> faults) {
        return (faults.isEmpty() ? EnumSet.noneOf(Fault.class) : EnumSet.copyOf(faults)).stream()
                .<Variant>map(Variant.Seeded::new).toList();
    }

    /** The seeded faults among the variants (all of them, for an experiment on the builtin car's faults). */
    public Set<Fault> faults() {
        return Set.copyOf(Variant.faultsOf(variants));
    }

    /**
     * Whether this is the paper's kind of experiment: the builtin car in process, its variants its seeded
     * faults. Its folders keep the columns, words and sections they always had; any other experiment's
     * controllers can fail as controllers and its variants need a key.
     */
    public boolean onBuiltinFaults() {
        return controller.equals(BUILTIN) && onlySeeded();
    }

    /** Whether every variant is a seeded fault of the builtin car (the folder then names them by {@code faults=}). */
    public boolean onlySeeded() {
        return variants.stream().allMatch(v -> v instanceof Variant.Seeded);
    }

    public boolean isSweep() {
        return !sweep.isEmpty();
    }

    /** How many replications {@link #plan()} holds: a sweep's map sets over all its budgets. */
    public int planSize() {
        return replications * Math.max(1, sweep.size());
    }

    /**
     * Every replication the experiment runs, in order: for a comparison one per replication; for a
     * sweep one per (budget, map set), budgets in the preset's order, map sets inside.
     */
    public List<PlannedReplication> plan() {
        List<PlannedReplication> plan = new ArrayList<>();
        if (!isSweep()) {
            for (int r = 0; r < replications; r++) {
                plan.add(new PlannedReplication(r, SeedPlan.replicationLabel(r), candidates, 0, r));
            }
            return plan;
        }
        for (int budget : sweep) {
            for (int set = 0; set < replications; set++) {
                plan.add(new PlannedReplication(plan.size(), SeedPlan.sweepLabel(budget, set), budget, budget, set));
            }
        }
        return plan;
    }

    public int driverIndex(String driver) {
        int i = drivers.indexOf(driver);
        if (i < 0) {
            throw new IllegalArgumentException("driver '" + driver + "' is not one of this experiment's " + drivers);
        }
        return i;
    }
}
