package sitcov.experiment;

import java.util.ArrayList;
import java.util.EnumSet;
import java.util.List;
import java.util.function.LongSupplier;
import java.util.random.RandomGenerator;
import sitcov.coverage.CoverageGrid;
import sitcov.coverage.GridDefinition;
import sitcov.engine.RandomStreams;
import sitcov.faults.Fault;
import sitcov.oracle.RunResult;
import sitcov.world.Layout;
import sitcov.world.MapGenerator;
import sitcov.world.WorldMap;

/**
 * One replication of the comparison: the coverage-filter driver over N candidates, then the random
 * driver over the same candidate sequence until it has spent the same budget. Every seed comes from
 * the master seed: candidates from the replication's {@code candidates} stream, a map's internal
 * seed from its external seed, so both drivers run a shared map identically.
 */
public final class Replication {
    private final ExperimentConfig config;
    private final int replication;
    private final LongSupplier nanoClock;
    private final List<Fault> faults;
    private final List<MapRun> runs = new ArrayList<>();
    private final List<CurvePoint> curve = new ArrayList<>();
    private final List<Long> mapNanos = new ArrayList<>();

    public Replication(ExperimentConfig config, int replication, LongSupplier nanoClock) {
        this.config = config;
        this.replication = replication;
        this.nanoClock = nanoClock;
        this.faults = List.copyOf(config.faults().isEmpty() ? EnumSet.noneOf(Fault.class) : EnumSet.copyOf(config.faults()));
    }

    /** The candidate external seeds of a replication, in order; both drivers read the same sequence. */
    public static RandomGenerator candidates(long masterSeed, int replication) {
        return new RandomStreams(masterSeed).derive("replication-" + replication).stream("candidates");
    }

    /** The internal seed of a map: fixed by the master seed and the map, whichever driver runs it. */
    public static long internalSeed(long masterSeed, long externalSeed) {
        return RandomStreams.mix(masterSeed, "internal-seed:" + externalSeed);
    }

    /** The coverage-filter driver alone, as in the paper's effort sweep (Fig. 4). */
    public ReplicationResult runCoverageOnly() {
        long start = nanoClock.getAsLong();
        coverageDriver(start);
        return new ReplicationResult(replication, runs, curve, mapNanos, nanoClock.getAsLong() - start, 0, 0);
    }

    public ReplicationResult run() {
        long start = nanoClock.getAsLong();
        long ticks = coverageDriver(start);
        long coverageNanos = nanoClock.getAsLong() - start;
        long randomStart = nanoClock.getAsLong();
        int randomCandidates = randomDriver(randomStart, ticks, coverageNanos);
        long randomNanos = nanoClock.getAsLong() - randomStart;
        return new ReplicationResult(replication, runs, curve, mapNanos, coverageNanos, randomNanos, randomCandidates);
    }

    private long coverageDriver(long start) {
        GridDefinition grid = config.grid();
        CoverageGrid cells = new CoverageGrid(grid);
        RandomGenerator candidates = candidates(config.masterSeed(), replication);
        long ticks = 0;
        int maps = 0;
        for (int i = 0; i < config.candidates(); i++) {
            long seed = candidates.nextLong();
            Layout layout = MapGenerator.layout(seed);
            double[] values = grid.values(layout);
            int cell = grid.cellOf(values);
            if (layout.isRunnable() && cells.add(cell)) {
                ticks += runMap(Method.COVERAGE_FILTER, i, seed, cell, values);
                maps++;
                curve.add(new CurvePoint(Method.COVERAGE_FILTER, replication, i + 1, maps, ticks, cells.covered(),
                        seconds(start)));
            }
        }
        curve.add(new CurvePoint(Method.COVERAGE_FILTER, replication, config.candidates(), maps, ticks, cells.covered(),
                seconds(start)));
        return ticks;
    }

    private int randomDriver(long start, long tickBudget, long nanoBudget) {
        GridDefinition grid = config.grid();
        CoverageGrid cells = new CoverageGrid(grid);
        RandomGenerator candidates = candidates(config.masterSeed(), replication);
        long ticks = 0;
        int maps = 0;
        int i = 0;
        // the budget is checked between maps: a map once started is finished, as in the paper
        while (config.budget() == BudgetKind.TICKS ? ticks < tickBudget : nanoClock.getAsLong() - start < nanoBudget) {
            long seed = candidates.nextLong();
            Layout layout = MapGenerator.layout(seed);
            double[] values = grid.values(layout);
            int cell = grid.cellOf(values);
            i++;
            if (!layout.isRunnable()) {
                continue;
            }
            boolean fresh = cells.add(cell);
            ticks += runMap(Method.RANDOM, i - 1, seed, cell, values);
            maps++;
            if (fresh) {
                curve.add(new CurvePoint(Method.RANDOM, replication, i, maps, ticks, cells.covered(), seconds(start)));
            }
        }
        curve.add(new CurvePoint(Method.RANDOM, replication, i, maps, ticks, cells.covered(), seconds(start)));
        return i;
    }

    private long runMap(Method method, int candidate, long seed, int cell, double[] values) {
        long t0 = nanoClock.getAsLong();
        WorldMap map = MapGenerator.generate(seed);
        long internal = internalSeed(config.masterSeed(), seed);
        RunResult faultFree = Simulator.run(map, internal);
        long ticks = faultFree.ticks();
        List<FaultVerdict> verdicts = new ArrayList<>(faults.size());
        for (Fault fault : faults) {
            RunRecord faulty = Simulator.run(map, internal, EnumSet.of(fault), RunObserver.NONE);
            ticks += faulty.result().ticks();
            verdicts.add(DifferentialOracle.judge(faultFree, faulty, fault));
        }
        runs.add(new MapRun(method, replication, candidate, seed, internal, cell, values, faultFree, verdicts, ticks));
        mapNanos.add(nanoClock.getAsLong() - t0);
        return ticks;
    }

    private double seconds(long start) {
        return (nanoClock.getAsLong() - start) / 1e9;
    }
}
