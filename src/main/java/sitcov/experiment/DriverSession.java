package sitcov.experiment;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.function.Supplier;
import java.util.random.RandomGenerator;
import sitcov.coverage.CoverageGrid;
import sitcov.coverage.GridDefinition;
import sitcov.judge.FaultOutcome;
import sitcov.judge.JudgedMap;
import sitcov.judge.MapRunner;
import sitcov.judge.RunSummary;
import sitcov.world.Layout;
import sitcov.world.MapGenerator;
import sitcov.world.WorldMap;

/**
 * One driver's share of one replication: the replication's candidate stream, the budget, and the
 * one way to run a map. Everything the driver spends is charged here. On a resumed run, the maps the
 * journal holds are replayed (same candidates, same decisions) instead of simulated again.
 */
public final class DriverSession {
    private final ExperimentRunner host;
    private final int replication;
    private final String driver;
    private final int driverIndex;
    private final Budget budget;
    private final RandomGenerator stream;
    private final String streamLabel;
    private RandomGenerator choices;
    private final GridDefinition grid;
    private final CoverageGrid cells;
    private final List<Journal.Entry> replay;
    private final Optional<Journal.Finished> finishedBefore;
    private final Driver self;
    private final SharedMaps shared;
    /** The lead this session feeds with its ticks as it spends them, when it is the replication's first driver. */
    private final Lead leading;
    /** Wall time charged for maps another driver of the replication judged: as if this driver had run them. */
    private long creditedNanos;
    private int drawn;
    private int mapsRun;
    private long ticks;
    private StopReason stop;
    private long elapsedOffset;
    private long liveSince;
    private long liveMapNanos;
    private int liveMaps;

    DriverSession(ExperimentRunner host, PlannedReplication replication, String driver, int driverIndex, Budget budget,
                  Journal journal, Driver self, SharedMaps shared, Lead leading) {
        this.shared = shared;
        this.leading = leading;
        this.host = host;
        this.replication = replication.index();
        this.driver = driver;
        this.driverIndex = driverIndex;
        this.budget = budget;
        this.stream = SeedPlan.candidates(host.config().masterSeed(), replication.streamLabel());
        this.streamLabel = replication.streamLabel();
        this.grid = host.config().grid();
        this.cells = new CoverageGrid(grid);
        this.replay = journal.maps(replication.index(), driver);
        this.finishedBefore = journal.finished(replication.index(), driver);
        this.liveSince = host.nanoTime();
        this.self = self;
    }

    /** Whether the driver may draw another candidate. Once false, it stays false. */
    public boolean budgetLeft() {
        host.checkHalt();
        if (stop != null) {
            return false;
        }
        if (finishedBefore.isPresent()) {
            stop = drawn < finishedBefore.get().spend().candidates() ? null : finishedBefore.get().spend().stoppedBy();
            return stop == null;
        }
        if (drawn >= budget.candidateLimit()) {
            stop = budget.measure() == StopReason.CANDIDATES ? StopReason.CANDIDATES : StopReason.CANDIDATE_LIMIT;
            return false;
        }
        Lead lead = budget.lead();
        boolean left = switch (budget.measure()) {
            case TICKS -> lead.ticksLeft(ticks, host::checkHalt);
            case WALL_CLOCK -> lead.nanosLeft(elapsedNanos());
            default -> true;
        };
        stop = left ? null : budget.measure();
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
        if (choices == null) {
            choices = SeedPlan.choices(host.config().masterSeed(), streamLabel, driver);
        }
        return choices;
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
        shared.claim(name, driver);
        double[] values = grid.values(situation.layout());
        return run(new MapId.Situation(name), -1, values, grid.cellOf(values), () -> situation, Optional.of(situation));
    }

    /**
     * Runs a situation the driver built in place of candidate {@code spent} (drawn and set aside, so a
     * search pays per candidate like a filter and every map's candidate is its place in the stream).
     */
    public MapRun run(String name, WorldMap situation, Candidate spent) {
        shared.claim(name, driver);
        double[] values = grid.values(situation.layout());
        return run(new MapId.Situation(name), spent.index(), values, grid.cellOf(values), () -> situation,
                Optional.of(situation));
    }

    private MapRun run(MapId id, int candidate, double[] criteria, int cell, Supplier<WorldMap> map,
                       Optional<WorldMap> built) {
        host.checkHalt();
        int index = mapsRun;
        if (index < replay.size()) {
            Journal.Entry e = replay.get(index);
            MapRun run = e.run();
            if (!run.map().equals(id) || run.candidate() != candidate || run.cell() != cell) {
                throw new IllegalStateException("the journal does not match this run: map " + index + " of driver " + driver
                        + " in replication " + replication + " is " + run.map().text() + " (candidate " + run.candidate()
                        + ") in the journal but " + id.text() + " (candidate " + candidate + ") now");
            }
            charge(run);
            if (index == replay.size() - 1) {
                elapsedOffset = e.driverNanos();
                liveSince = host.nanoTime();
            }
            host.emit(new ExperimentEvent.MapJudged(run, built, true, e.mapNanos(), e.driverNanos(), driverIndex,
                    progress()));
            return run;
        }
        long start = host.nanoTime();
        long internal = SeedPlan.internalSeed(host.config().masterSeed(), id);
        SharedMaps.Judged judgedBefore = shared.judged(id);
        WorldMap world;
        JudgedMap judged;
        if (judgedBefore != null) {
            // the same map and seeds run the same: judged once, charged to every driver that runs it
            world = judgedBefore.world();
            judged = judgedBefore.judged();
        } else {
            world = map.get();
            judged = MapRunner.judge(world, internal, host.faults(), host.config().faultyRuns());
        }
        List<Double> values = new ArrayList<>(criteria.length);
        for (double v : criteria) {
            values.add(v);
        }
        MapRun run = new MapRun(replication, driver, index, candidate, id, world.seed(), internal, cell, values,
                RunSummary.of(judged.faultFree()), judged.verdicts().stream().map(FaultOutcome::of).toList());
        charge(run);
        long nanos = host.nanoTime() - start;
        if (judgedBefore != null) {
            creditedNanos += judgedBefore.nanos() - nanos;
            nanos = judgedBefore.nanos();
        } else {
            shared.keep(id, new SharedMaps.Judged(world, judged, nanos));
        }
        liveMapNanos += nanos;
        liveMaps++;
        host.emit(new ExperimentEvent.MapJudged(run, built, false, nanos, elapsedNanos(), driverIndex, progress()));
        return run;
    }

    private void charge(MapRun run) {
        mapsRun++;
        ticks += run.ticks();
        cells.add(run.cell());
        if (leading != null) {
            leading.spent(ticks);
        }
    }

    /** Wall time this driver has spent; while replaying the journal, the time the journal recorded. */
    long elapsedNanos() {
        if (mapsRun < replay.size()) {
            return mapsRun == 0 ? 0 : replay.get(mapsRun - 1).driverNanos();
        }
        return elapsedOffset + host.nanoTime() - liveSince + creditedNanos;
    }

    /** How much of its budget the driver has spent, 0..1. */
    public double budgetSpent() {
        long amount = budget.lead() == null ? budget.amount() : budget.lead().soFar(budget.measure(), elapsedNanos());
        double s = switch (budget.measure()) {
            case TICKS -> amount == 0 ? 1 : (double) ticks / amount;
            case WALL_CLOCK -> amount == 0 ? 1 : (double) elapsedNanos() / amount;
            default -> (double) drawn / amount;
        };
        return Math.min(1, Math.max(0, s));
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
        return budget.measure() == StopReason.CANDIDATES ? budget.amount() - drawn : -1;
    }

    /** What drawing a candidate has cost against judging a map, in wall time (0 before a map was judged). */
    public double candidateCostInMaps() {
        if (liveMaps == 0 || drawn == 0) {
            return 0;
        }
        double perMap = (double) liveMapNanos / liveMaps;
        double perCandidate = Math.max(0, elapsedNanos() - liveMapNanos) / (double) drawn;
        return perCandidate / perMap;
    }

    /** What the driver spent; for a driver the journal shows finished, checked against the journal. */
    Journal.Finished finish() {
        DriverSpend spend = new DriverSpend(replication, driver, drawn, mapsRun, ticks, cells.covered(),
                stop == null ? StopReason.DRIVER : stop);
        if (finishedBefore.isPresent()) {
            if (!finishedBefore.get().spend().equals(spend)) {
                throw new IllegalStateException("the journal does not match this run: driver " + driver + " in replication "
                        + replication + " finished with " + finishedBefore.get().spend() + " but replays to " + spend);
            }
            return finishedBefore.get();
        }
        return new Journal.Finished(spend, elapsedNanos());
    }

    boolean wasFinishedBefore() {
        return finishedBefore.isPresent();
    }
}
