package sitcov.experiment;

import java.util.List;
import java.util.Optional;
import java.util.function.Supplier;
import java.util.random.RandomGenerator;
import sitcov.coverage.CoverageGrid;
import sitcov.coverage.GridDefinition;
import sitcov.judge.Requirement;
import sitcov.world.Layout;
import sitcov.world.MapGenerator;
import sitcov.world.WorldMap;

/**
 * One driver's share of one replication: the replication's candidate stream, the budget the
 * {@link ReplicationPlan} gave it, and the one way to run a map ({@link SessionJudge}: judged now, or
 * replayed from the journal of a resumed run). Everything the driver spends is charged here.
 */
public final class DriverSession {
    private final ExperimentRunner host;
    private final int replication;
    private final String driver;
    private final int driverIndex;
    private final Budget budget;
    private final RandomGenerator stream;
    private final RandomGenerator choices;
    private final GridDefinition grid;
    private final CoverageGrid cells;
    private final Optional<Journal.Finished> finishedBefore;
    private final Driver self;
    private final SharedMaps shared;
    private final DriverClock clock;
    private final SessionJudge judge;
    private int drawn;
    private int mapsRun;
    private long ticks;
    private StopReason stop;

    DriverSession(ExperimentRunner host, ReplicationPlan plan, int driverIndex, Journal journal, Driver self) {
        PlannedReplication p = plan.replication();
        this.host = host;
        this.replication = p.index();
        this.driver = host.config().drivers().get(driverIndex);
        this.driverIndex = driverIndex;
        this.budget = plan.budget(driverIndex);
        this.stream = SeedPlan.candidates(host.config().masterSeed(), p.streamLabel());
        this.choices = SeedPlan.choices(host.config().masterSeed(), p.streamLabel(), driver);
        this.grid = host.config().grid();
        this.cells = new CoverageGrid(grid);
        this.finishedBefore = journal.finished(replication, driver);
        this.self = self;
        this.shared = plan.shared();
        List<Journal.Entry> replay = journal.maps(replication, driver);
        this.clock = new DriverClock(host::nanoTime, !replay.isEmpty());
        this.judge = JournalReplay.over(replay, new FreshJudge(host, replication, driver, shared, clock), clock);
    }

    /** Whether the driver may draw another candidate. Once false, it stays false. */
    public boolean budgetLeft() {
        host.checkHalt();
        if (stop != null) {
            return false;
        }
        if (finishedBefore.isPresent()) {
            stop = finishedBefore.get().stopAt(drawn);
            return stop == null;
        }
        if (drawn >= budget.candidateLimit()) {
            stop = budget.atLimit();
            return false;
        }
        boolean left = budget.left(ticks, clock.elapsed(), host::checkHalt);
        stop = left ? null : budget.spentOut();
        return left;
    }

    /** The next candidate of the replication's stream (every driver of a replication reads the same sequence). */
    public Candidate nextCandidate() {
        host.checkHalt();
        if (drawn >= budget.candidateLimit()) {
            throw new IllegalStateException("driver " + driver + " drew past its limit of " + budget.candidateLimit()
                    + " candidates; check budgetLeft() before each draw");
        }
        Layout layout = MapGenerator.layout(stream.nextLong());
        double[] values = grid.values(layout);
        return new Candidate(drawn++, layout, values, grid.cellOf(values));
    }

    /** The cell a layout falls in ({@link sitcov.coverage.Bins#INVALID} outside the grid). */
    public int cellOf(Layout layout) {
        return grid.cellOf(grid.values(layout));
    }

    public GridDefinition grid() {
        return grid;
    }

    /** The replication this session runs (names of built situations carry it, so they are unique). */
    public int replication() {
        return replication;
    }

    /** The stream of this driver's own choices in this replication (which situation to edit, how). */
    public RandomGenerator choices() {
        return choices;
    }

    /**
     * The reference's own requirement this session's campaign trial falsifies, for a driver that steers by how
     * near the reference came to violating it; empty for every other experiment.
     */
    public Optional<Requirement> requirement() {
        return host.config().requirement();
    }

    /** Whether a map this driver ran already fills {@code cell}. */
    public boolean covers(int cell) {
        return cells.isCovered(cell);
    }

    public int cellsCovered() {
        return cells.covered();
    }

    /** Runs a drawn candidate: fault-free and once per fault, judged; charged to this driver. */
    public MapRun run(Candidate c) {
        if (!c.runnable()) {
            throw new IllegalArgumentException("candidate " + c.index() + " (seed " + c.externalSeed()
                    + ") has no Target or car start and cannot be run");
        }
        return run(new MapId.Seeded(c.externalSeed()), c.index(), c.criteria(), c.cell(),
                () -> MapGenerator.withMovingCars(c.layout()), Optional.empty());
    }

    /**
     * Runs a situation the driver built; {@code name} must be unique in the experiment (it names its file).
     *
     * @throws IllegalStateException when the name was run before in this replication, by any driver
     */
    public MapRun run(String name, WorldMap situation) {
        return run(name, situation, -1);
    }

    /**
     * Runs a situation the driver built in place of candidate {@code spent} (drawn and set aside, so a
     * search pays per candidate like a filter and every map's candidate is its place in the stream).
     */
    public MapRun run(String name, WorldMap situation, Candidate spent) {
        return run(name, situation, spent.index());
    }

    private MapRun run(String name, WorldMap situation, int candidate) {
        shared.claim(name, driver);
        double[] values = grid.values(situation.layout());
        return run(new MapId.Situation(name), candidate, values, grid.cellOf(values), () -> situation,
                Optional.of(situation));
    }

    private MapRun run(MapId id, int candidate, double[] criteria, int cell, Supplier<WorldMap> map,
                       Optional<WorldMap> built) {
        host.checkHalt();
        SessionJudge.Judgement j = judge.judge(new SessionJudge.Request(mapsRun, id, candidate, criteria, cell, map));
        MapRun run = j.run();
        mapsRun++;
        ticks += run.ticks();
        cells.add(run.cell());
        budget.charged(ticks);
        budget.judged(run);
        host.emit(new ExperimentEvent.MapJudged(run, built, j.replayed(), j.mapNanos(), j.driverNanos(), driverIndex,
                progress(), j.recordings()));
        return run;
    }

    /** How much of its budget the driver has spent, 0..1. */
    public double budgetSpent() {
        return Math.min(1, Math.max(0, budget.share(drawn, ticks, clock.elapsed())));
    }

    private double progress() {
        return Math.min(1, Math.max(0, self.progress(this)));
    }

    public int candidatesDrawn() {
        return drawn;
    }

    public int mapsRun() {
        return mapsRun;
    }

    /** Candidates the driver may still draw when its budget is a number of candidates (it is the first driver), else -1. */
    public long candidatesLeft() {
        return budget instanceof Budget.Candidates c ? c.count() - drawn : -1;
    }

    /** What drawing a candidate has cost against judging a map, in wall time (0 before a map was judged). */
    public double candidateCostInMaps() {
        return clock.candidateCostInMaps(drawn);
    }

    /** What the driver spent; for a driver the journal shows finished, checked against the journal. */
    Journal.Finished finish() {
        DriverSpend spend = new DriverSpend(replication, driver, drawn, mapsRun, ticks, cells.covered(),
                stop == null ? StopReason.DRIVER : stop);
        return finishedBefore.map(f -> f.replayedTo(spend)).orElseGet(() -> new Journal.Finished(spend, clock.elapsed()));
    }

    boolean wasFinishedBefore() {
        return finishedBefore.isPresent();
    }
}
