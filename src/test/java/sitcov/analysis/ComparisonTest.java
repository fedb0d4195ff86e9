package sitcov.analysis;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import sitcov.coverage.GridDefinition;
import sitcov.experiment.AnalysisPlan;
import sitcov.experiment.BudgetKind;
import sitcov.experiment.Direction;
import sitcov.experiment.ExperimentConfig;
import sitcov.experiment.MapRun;
import sitcov.experiment.Measure;
import sitcov.experiment.ReplicationResult;
import sitcov.faults.FaultSet;
import sitcov.judge.FaultyRuns;
import sitcov.stats.FisherExact;

public class ComparisonTest {
    static final ExperimentConfig SIX = config(6, List.of("coverage-filter", "random"));

    public static ExperimentConfig config(int replications, List<String> drivers) {
        return new ExperimentConfig("verdict", 1, 10, replications, FaultSet.parse("14,19"), BudgetKind.TICKS,
                GridDefinition.paper(), drivers, List.of(), 100, FaultyRuns.UNTIL_VERDICT);
    }

    /**
     * Six replications: the filter's three maps fill three cells and each finds fault 14; random's
     * three maps share one cell and find nothing. Fault 19 is found by neither. Every map costs 300 ticks.
     */
    public static Summary filterCoversAndFindsMore() {
        List<ReplicationResult> results = new ArrayList<>();
        for (int r = 0; r < 6; r++) {
            List<MapRun> filter = new ArrayList<>();
            List<MapRun> random = new ArrayList<>();
            for (int i = 0; i < 3; i++) {
                filter.add(DiscoveryTest.map("coverage-filter", i, 10 * r + i, 10 + i, "F-"));
                random.add(DiscoveryTest.map("random", i, 100 + 10 * r + i, 50, "--"));
            }
            results.add(new ReplicationResult(r, List.of(DiscoveryTest.run("coverage-filter", filter.toArray(MapRun[]::new)),
                    DiscoveryTest.run("random", random.toArray(MapRun[]::new)))));
        }
        return new Summary(SIX, results);
    }

    /**
     * n replications: in replication k the filter runs k + 2 maps in as many cells, random as many maps in
     * one cell; each of the filter's maps finds fault 14, and random's find what {@code randomMarks} says.
     * Every map costs 300 ticks.
     */
    public static Summary filterAheadByUntiedAmounts(int n, String randomMarks) {
        List<ReplicationResult> results = new ArrayList<>();
        for (int r = 0; r < n; r++) {
            List<MapRun> filter = new ArrayList<>();
            List<MapRun> random = new ArrayList<>();
            for (int i = 0; i < r + 2; i++) {
                filter.add(DiscoveryTest.map("coverage-filter", i, 10 * r + i, 10 + i, "F-"));
                random.add(DiscoveryTest.map("random", i, 100 + 10 * r + i, 50, randomMarks));
            }
            results.add(new ReplicationResult(r, List.of(DiscoveryTest.run("coverage-filter", filter.toArray(MapRun[]::new)),
                    DiscoveryTest.run("random", random.toArray(MapRun[]::new)))));
        }
        ExperimentConfig config = config(n, List.of("coverage-filter", "random"));
        return new Summary(config, results);
    }

    @Test
    void aTestWhoseSmallestPIsAboveItsFamilysLevelCouldHaveDetectedNothing() {
        Comparison c = Comparison.of(SIX, filterAheadByUntiedAmounts(6, "--"), new SplittableRandom(4));
        // cells covered differ by k + 1 = 1..6, the area by (k + 1) / (2 (k + 2)) (the filter's first map of k + 2
        // finds one fault of two): untied, so the smallest p is 2/2^6 = 0.03125, above 0.05 / 2 places; Holm
        // over the two places: 2 × 0.03125 = 0.0625, not shown
        MeasureComparison cells = measure(c, Measure.CELLS_COVERED);
        assertEquals(new Families(2, 2, 2, 1, 1), c.families(), "the TOSTs join the two places");
        assertEquals(0.03125, cells.paired().smallestP(), 1e-12);
        assertEquals(0.0625, cells.paired().pAdjusted(), 1e-12);
        assertEquals(Finding.INCONCLUSIVE, cells.finding());
        assertTrue(Double.isInfinite(cells.paired().detectable()));
        assertEquals(Finding.INCONCLUSIVE, measure(c, Measure.DISCOVERY_AREA).finding());
    }

    static MeasureComparison measure(Comparison c, Measure m) {
        return c.measures().stream().filter(t -> t.measure() == m).findFirst().orElseThrow();
    }

    @Test
    void thePrimaryQuestionIsTestedOnItsOwnTheMeasuresByClosedTestingAndTheFaultsByBenjaminiHochberg() {
        Comparison c = Comparison.of(SIX, filterCoversAndFindsMore(), new SplittableRandom(3));
        // six tied differences of one sign: W+ = 21, variance 6*7*13/24 - (6^3 - 6)/48 = 18.375,
        // z = (21 - 10.5 - 0.5) / sqrt(18.375) = 2.333, two-sided p = 0.0196 (continuity-corrected)
        MeasureComparison faults = measure(c, Measure.FAULTS_FOUND);
        assertTrue(faults.primary());
        assertEquals(0.0196, faults.paired().p(), 1e-4);
        assertEquals(faults.paired().p(), faults.paired().pAdjusted(), 0, "the primary test is reported as is");
        assertEquals(Finding.HIGHER_A, faults.finding());
        // the measures' family: cells covered and the area under the discovery curve, each p = 0.0196, two
        // places (their TOSTs have no spread, every difference alike, and stay out, as do the untestable rows);
        // the faults' screening family: fault 14 alone, p = 0.0196
        assertEquals(new Families(2, 2, 0, 1, 1), c.families());
        MeasureComparison cells = measure(c, Measure.CELLS_COVERED);
        assertEquals(3, cells.paired().meanA(), 1e-12);
        assertEquals(1, cells.paired().meanB(), 1e-12);
        assertEquals(2, cells.paired().difference().low(), 1e-12, "every resample of +2s has mean 2");
        assertEquals(2 * cells.paired().p(), cells.paired().pAdjusted(), 1e-12, "Holm over two places: 2 × 0.0196");
        assertEquals(Finding.HIGHER_A, cells.finding(), "0.039 < 0.05");
        FaultComparison f14 = c.faults().get(0);
        assertEquals(f14.paired().p(), f14.paired().pAdjusted(), 1e-12, "BH over one test: q = p");
        assertEquals(Finding.HIGHER_A, f14.finding());
        assertEquals(6, cells.paired().higherA(), "the filter covers more in all six replications");
        assertEquals(1.0, cells.paired().superiority(), 0);
    }

    @Test
    void constantAndDuplicatedMeasuresAndFaultsFoundByNeitherAreNotTestable() {
        Comparison c = Comparison.of(SIX, filterCoversAndFindsMore(), new SplittableRandom(3));
        MeasureComparison maps = measure(c, Measure.MAPS_RUN);
        assertEquals(Finding.NOT_TESTABLE, maps.finding());
        assertEquals("it is 3 in every replication of both", maps.note());
        MeasureComparison perMap = measure(c, Measure.AVG_MAP_FAULT);
        assertEquals(Finding.NOT_TESTABLE, perMap.finding(), "one fault found on every map: 1 per map, as faults found");
        assertEquals("the same numbers as distinct faults found for this pair", perMap.note());
        FaultComparison f19 = c.faults().get(1);
        assertEquals(Finding.NOT_TESTABLE, f19.finding());
        assertTrue(Double.isNaN(f19.oddsRatio()), "no odds ratio of nothing against nothing");
        assertTrue(Double.isNaN(f19.paired().pAdjusted()));
    }

    @Test
    void aClusteredDriverThatPooledFisherCallsDifferentIsNotDifferentReplicationByReplication() {
        // ten replications of 20 maps each: a search finds fault 14 on every map of two replications and on none
        // of the other eight (its elites held the situation there); random finds it on 1 map of 20 in each
        List<ReplicationResult> results = new ArrayList<>();
        for (int r = 0; r < 10; r++) {
            List<MapRun> search = new ArrayList<>();
            List<MapRun> random = new ArrayList<>();
            for (int i = 0; i < 20; i++) {
                search.add(DiscoveryTest.map("coverage-search", i, 100 * r + i, i, r < 2 ? "F-" : "--"));
                random.add(DiscoveryTest.map("random", i, 100 * r + i, i, i == 0 ? "F-" : "--"));
            }
            results.add(new ReplicationResult(r, List.of(DiscoveryTest.run("coverage-search", search.toArray(MapRun[]::new)),
                    DiscoveryTest.run("random", random.toArray(MapRun[]::new)))));
        }
        ExperimentConfig config = config(10, List.of("coverage-search", "random"));
        FaultComparison f14 = Comparison.of(config, new Summary(config, results),
                new SplittableRandom(5)).faults().get(0);
        // pooled over all maps, 40 of 200 against 10 of 200: Fisher's exact test calls that a difference
        assertEquals(List.of(40L, 200L, 10L, 200L), List.of(f14.foundA(), f14.mapsA(), f14.foundB(), f14.mapsB()));
        assertEquals(FisherExact.test(40, 160, 10, 190).p(), f14.pFisher(), 0);
        assertTrue(f14.pFisher() < 1e-4, "pooled p = " + f14.pFisher());
        // per replication the differences of shares are +0.95 twice and -0.05 eight times: ranks 9.5 (twice) and
        // 4.5, W+ = 19 of 55, variance 10*11*21/24 - (8^3 - 8 + 2^3 - 2)/48 = 85.625,
        // z = (19 - 27.5 + 0.5) / 9.2534 = -0.8646, p = 0.387: no difference shown
        assertEquals(0.387, f14.paired().p(), 1e-3);
        assertEquals(Finding.INCONCLUSIVE, f14.finding());
        // the search's finds are over-dispersed: p = 0.2, X^2 = 2 * 16^2 / 3.2 + 8 * 4^2 / 3.2 = 200 over 9 df;
        // random's are exactly at their pooled share
        assertEquals(200 / 9.0, f14.dispersionA(), 1e-9);
        assertEquals(0, f14.dispersionB(), 1e-12);
    }

    @Test
    void aDriverThatOvershotIsComparedOverTheTicksBothSpent() {
        // the filter spends 900 ticks (three maps); random's fourth map ends at 1200 and is the only one finding
        // fault 19: within the ticks both spent, random found nothing
        List<ReplicationResult> results = new ArrayList<>();
        for (int r = 0; r < 6; r++) {
            results.add(new ReplicationResult(r, List.of(
                    DiscoveryTest.run("coverage-filter", DiscoveryTest.map("coverage-filter", 0, 0, 1, "F-"),
                            DiscoveryTest.map("coverage-filter", 1, 1, 2, "--"), DiscoveryTest.map("coverage-filter", 2, 2, 3, "--")),
                    DiscoveryTest.run("random", DiscoveryTest.map("random", 0, 0, 1, "--"), DiscoveryTest.map("random", 1, 1, 1, "--"),
                            DiscoveryTest.map("random", 2, 2, 1, "--"), DiscoveryTest.map("random", 3, 3, 4, "-F")))));
        }
        Comparison c = Comparison.of(SIX, new Summary(SIX, results), new SplittableRandom(1));
        assertEquals(0, measure(c, Measure.FAULTS_FOUND).paired().meanB(), 0);
        assertEquals(3, measure(c, Measure.MAPS_RUN).paired().meanB(), 0, "the map ending past 900 ticks is left out");
        assertEquals(1, measure(c, Measure.CELLS_COVERED).paired().meanB(), 0);
        assertEquals(Finding.NOT_TESTABLE, c.faults().get(1).finding(), "fault 19 was found only past the horizon");
    }

    @Test
    void aPairsComparisonDoesNotDependOnWhichOtherDriversRan() {
        Summary two = filterCoversAndFindsMore();
        List<ReplicationResult> withThird = new ArrayList<>();
        for (ReplicationResult r : two.results()) {
            withThird.add(new ReplicationResult(r.replication(), List.of(r.of("coverage-filter"), r.of("random"),
                    DiscoveryTest.run("every-other", DiscoveryTest.map("every-other", 0, 0, 1, "--")))));
        }
        ExperimentConfig three = config(6, List.of("coverage-filter", "random", "every-other"));
        Comparison c = Comparison.of(three, new Summary(three, withThird), new SplittableRandom(3));
        MeasureComparison area = c.measures().stream().filter(m -> m.measure() == Measure.DISCOVERY_AREA
                && m.driverB().equals("random")).findFirst().orElseThrow();
        // the filter finds fault 14 with its first map (300 ticks) of 900: area (900 - 300) / (900 * 2) = 1/3,
        // over the ticks this pair spent — not the 300 the third driver stopped at
        assertEquals(1 / 3.0, area.paired().meanA(), 1e-12);
    }

    @Test
    void aMeasureWhosePairedDifferencesStayWithinTheMarginIsEquivalent() {
        // thirty replications: random finds fault 14 on its one map like the filter, except 19 is found too in
        // replications 0, 3, 6, ... and nothing in 1, 4, 7, ...: faults found differ by 0, +1, -1 in turn
        List<ReplicationResult> results = new ArrayList<>();
        for (int r = 0; r < 30; r++) {
            String marks = switch (r % 3) {
                case 0 -> "FF";
                case 1 -> "--";
                default -> "F-";
            };
            results.add(new ReplicationResult(r, List.of(DiscoveryTest.run("coverage-filter",
                    DiscoveryTest.map("coverage-filter", 0, 0, 1, "F-")), DiscoveryTest.run("random",
                    DiscoveryTest.map("random", 0, 0, 1, marks)))));
        }
        ExperimentConfig config = new ExperimentConfig("verdict", 1, 10, 30, FaultSet.parse("14,19"), BudgetKind.TICKS,
                GridDefinition.paper(), List.of("coverage-filter", "random"), List.of(), 100, FaultyRuns.UNTIL_VERDICT,
                new AnalysisPlan(Measure.FAULTS_FOUND, List.of("random", "coverage-filter"), Direction.TWO_SIDED, Map.of()));
        MeasureComparison faults = measure(Comparison.of(config, new Summary(config, results), new SplittableRandom(2)),
                Measure.FAULTS_FOUND);
        // differences (filter - random) -1, +1, 0 ten times each: mean 0, sd sqrt(20/29) = 0.8305, se 0.1516;
        // t = (0 + 1) / 0.1516 = 6.60 on 29 df for each bound: p far below 0.05
        assertEquals(Finding.EQUIVALENT, faults.finding());
        assertTrue(faults.pTost() < 1e-5, "TOST p = " + faults.pTost());
        assertEquals(0, faults.paired().difference().estimate(), 1e-12);
        assertEquals(1.0, faults.paired().p(), 1e-12, "ten +1 and ten -1: W+ is its mean, p = 1");
    }

    @Test
    void theSameSeedGivesTheSameIntervals() {
        Summary s = filterCoversAndFindsMore();
        assertEquals(Comparison.of(SIX, s, new SplittableRandom(9)).measures(),
                Comparison.of(SIX, s, new SplittableRandom(9)).measures());
        assertEquals(Measure.PAPER.size(), Comparison.of(SIX, s, new SplittableRandom(9)).measures().size());
    }

    @Test
    void noReplicationsLeaveEveryTestNotTestableRatherThanFailing() {
        // what a shard of more shards than replications holds (run refuses such a shard now; older folders remain)
        Comparison c = Comparison.of(SIX, new Summary(SIX, List.of()), new SplittableRandom(3));
        assertEquals(0, c.replications());
        assertEquals(Measure.PAPER.size(), c.measures().size());
        for (MeasureComparison m : c.measures()) {
            assertEquals(Finding.NOT_TESTABLE, m.finding(), m.measure().toString());
            assertEquals("there are no replications to compare", m.note());
            assertTrue(Double.isNaN(m.a12()) && Double.isNaN(m.paired().difference().estimate()));
            assertEquals(sitcov.stats.EffectSize.UNDEFINED, m.effect());
        }
        assertEquals(2, c.faults().size());
        for (FaultComparison f : c.faults()) {
            assertEquals(Finding.NOT_TESTABLE, f.finding());
            assertEquals("there are no replications to compare", f.note());
        }
        assertEquals(0, c.families().tests());
    }
}
