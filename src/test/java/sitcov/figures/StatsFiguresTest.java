package sitcov.figures;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.SplittableRandom;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import sitcov.analysis.Comparison;
import sitcov.analysis.FaultComparison;
import sitcov.analysis.Summary;
import sitcov.coverage.GridDefinition;
import sitcov.experiment.AnalysisPlan;
import sitcov.experiment.BudgetKind;
import sitcov.experiment.Direction;
import sitcov.experiment.DriverRun;
import sitcov.experiment.DriverSpend;
import sitcov.experiment.ExperimentConfig;
import sitcov.experiment.MapId;
import sitcov.experiment.MapRun;
import sitcov.experiment.Measure;
import sitcov.experiment.ReplicationResult;
import sitcov.experiment.StopReason;
import sitcov.faults.Fault;
import sitcov.faults.FaultSet;
import sitcov.judge.Detection;
import sitcov.judge.FaultOutcome;
import sitcov.judge.FaultyRuns;
import sitcov.judge.RunSummary;
import sitcov.oracle.AccidentType;
import sitcov.oracle.Outcome;
import sitcov.results.ResultsFolder;

class StatsFiguresTest {
    private static final List<String> DRIVERS = List.of("coverage-filter", "random", "every-other");
    /** The primary question names the last two drivers, the later one first. */
    private static final ExperimentConfig CONFIG = new ExperimentConfig("figures", 1, 10, 3, FaultSet.parse("14,19"),
            BudgetKind.TICKS, GridDefinition.paper(), DRIVERS, List.of(), 100, FaultyRuns.UNTIL_VERDICT,
            new AnalysisPlan(Measure.FAULTS_FOUND, List.of("every-other", "random"), Direction.TWO_SIDED, Map.of()));
    private static final RunSummary SAFE = new RunSummary(Outcome.TARGET_REACHED, 100, List.of(0L, 0L, 0L, 0L, 0L));

    /** Map {@code index} in {@code cell}; found marks per fault (14, 19): F found, - not. */
    private static MapRun map(int replication, String driver, int index, int cell, String marks) {
        List<FaultOutcome> faults = new ArrayList<>();
        List<Fault> ids = List.of(Fault.TARGET_LANE_CHECK_SKIPPED, Fault.ONCOMING_AT_HALF_SPEED);
        for (int f = 0; f < 2; f++) {
            boolean found = marks.charAt(f) == 'F';
            faults.add(new FaultOutcome(new sitcov.judge.Variant.Seeded(ids.get(f)), SAFE, true, true, 1, found ? Detection.FOUND : Detection.EFFECT_NO_FAILURE,
                    found ? Optional.of(sitcov.oracle.Failure.LEAVEROAD) : Optional.empty(), found));
        }
        return new MapRun(replication, driver, index, index, new MapId.Seeded(index), index, index, cell,
                List.of(0.0, 0.0, 0.0), SAFE, faults);
    }

    private static DriverRun run(int replication, String driver, MapRun... maps) {
        long cells = List.of(maps).stream().mapToInt(MapRun::cell).distinct().count();
        return new DriverRun(driver, List.of(maps), new DriverSpend(replication, driver, 10, maps.length,
                List.of(maps).stream().mapToLong(MapRun::ticks).sum(), (int) cells, StopReason.CANDIDATES));
    }

    /**
     * Three replications: the filter and random find fault 14 on every map, every-other on one map of
     * three; nobody finds fault 19.
     */
    private static Summary summary() {
        List<ReplicationResult> results = new ArrayList<>();
        for (int r = 0; r < 3; r++) {
            results.add(new ReplicationResult(r, List.of(
                    run(r, "coverage-filter", map(r, "coverage-filter", 0, 1, "F-"), map(r, "coverage-filter", 1, 2, "F-")),
                    run(r, "random", map(r, "random", 0, 1, "F-"), map(r, "random", 1, 1, "F-")),
                    run(r, "every-other", map(r, "every-other", 0, 3, "F-"), map(r, "every-other", 1, 3, "--"),
                            map(r, "every-other", 2, 4, "--")))));
        }
        return new Summary(CONFIG, results);
    }

    private static Comparison comparison(Summary summary) {
        return Comparison.of(CONFIG, summary, new SplittableRandom(1));
    }

    @Test
    void everyPairOfDriversHasAPairTheFiguresDrawThePrimaryQuestionsFirst() {
        Summary summary = summary();
        List<StatsFigures.Pair> pairs = StatsFigures.pairs(summary, comparison(summary));
        assertEquals(List.of(new StatsFigures.Pair("random", "every-other", true),
                new StatsFigures.Pair("coverage-filter", "random", false),
                new StatsFigures.Pair("coverage-filter", "every-other", false)), pairs);
    }

    @Test
    void eachPairGetsItsOwnForestPlotNamedInPairOrderAndStaleOnesAreRemoved(@TempDir Path dir) throws Exception {
        Files.writeString(dir.resolve("fig-faults-odds-ratios.png"), "drawn by an older version");
        Files.writeString(dir.resolve(ResultsFolder.forestPlot(4, "a", "b")), "a pair this folder no longer has");
        Files.writeString(dir.resolve("fig-other.png"), "not a forest plot");
        Summary summary = summary();
        StatsFigures.writeAll(summary, comparison(summary), dir);
        List<String> expected = List.of(ResultsFolder.forestPlot(1, "random", "every-other"),
                ResultsFolder.forestPlot(2, "coverage-filter", "random"),
                ResultsFolder.forestPlot(3, "coverage-filter", "every-other"));
        try (Stream<Path> files = Files.list(dir)) {
            List<String> forest = files.map(p -> p.getFileName().toString()).filter(ResultsFolder::isForestPlot).sorted()
                    .toList();
            assertEquals(expected, forest, "one per pair, the primary pair's first in name order, nothing stale");
        }
        assertTrue(Files.exists(dir.resolve("fig-other.png")));
        for (String name : expected) {
            assertTrue(javax.imageio.ImageIO.read(dir.resolve(name).toFile()).getHeight() > 100, name);
        }
        assertTrue(Files.exists(dir.resolve(ResultsFolder.FIG_MEASURES)) && Files.exists(dir.resolve(ResultsFolder.FIG_DISCOVERY)));
    }

    @Test
    void aFaultFoundByNeitherOrOnEveryMapByBothSaysSoInsteadOfARatio() {
        Summary summary = summary();
        List<FaultComparison> faults = comparison(summary).faults();
        FaultComparison bothEverywhere = faults.stream()
                .filter(t -> t.driverB().equals("random") && t.variant().id() == 14).findFirst().orElseThrow();
        FaultComparison neither = faults.stream().filter(t -> t.driverB().equals("random") && t.variant().id() == 19)
                .findFirst().orElseThrow();
        FaultComparison differs = faults.stream().filter(t -> t.driverA().equals("coverage-filter")
                && t.driverB().equals("every-other") && t.variant().id() == 14).findFirst().orElseThrow();
        assertEquals(Optional.of("found on every map by both"), StatsFigures.noRatio(bothEverywhere));
        assertEquals(Optional.of("found by neither driver"), StatsFigures.noRatio(neither));
        assertEquals(Optional.empty(), StatsFigures.noRatio(differs), "6 of 6 against 3 of 9 has a ratio");
    }

    @Test
    void theStripOfDistinctFaultsFoundEndsAtTheExperimentsFaultsAndCountsAreLabelledWhole() {
        Axis faults = StatsFigures.axis(Measure.FAULTS_FOUND, 3, 7);
        assertEquals(7, faults.last(), 0, "seven faults: the axis ends at 7, not 10");
        assertTrue(faults.end() > 7, "a replication that found all 7 sits inside the frame");
        Axis cells = StatsFigures.axis(Measure.CELLS_COVERED, 45, 7);
        cells.ticks().forEach(t -> assertEquals(Math.rint(t), t, 0));
        assertTrue(cells.end() > cells.last() && cells.last() >= 45);
        assertFalse(StatsFigures.axis(Measure.DISCOVERY_AREA, 0.5, 7).ticks().stream().allMatch(t -> t == Math.rint(t)),
                "a share is labelled in fractions");
    }
}
