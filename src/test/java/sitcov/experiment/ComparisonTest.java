package sitcov.experiment;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import sitcov.coverage.GridDefinition;
import sitcov.faults.FaultSet;
import sitcov.stats.EffectSize;

public class ComparisonTest {
    /**
     * Six replications: the filter's three maps fill three cells and each finds fault 14; random's
     * three maps share one cell and find nothing. Fault 19 is found by neither.
     */
    public static Summary filterCoversAndFindsMore() {
        ExperimentConfig config = new ExperimentConfig("verdict", 1, 10, 6, FaultSet.parse("14,19"), BudgetKind.TICKS,
                GridDefinition.paper());
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
        return new Summary(config, results);
    }

    @Test
    void aDifferenceInEveryPairedReplicationIsSignificantWithALargeEffect() {
        Comparison c = Comparison.of(filterCoversAndFindsMore(), new SplittableRandom(3));
        Comparison.MeasureTest cells = c.measures().stream()
                .filter(m -> m.measure() == Comparison.Measure.CELLS_COVERED).findFirst().orElseThrow();
        assertEquals(3, cells.meanA(), 1e-12);
        assertEquals(1, cells.meanB(), 1e-12);
        // every paired difference is 2, so every bootstrap resample's mean is 2
        assertEquals(2, cells.difference().estimate(), 1e-12);
        assertEquals(2, cells.difference().low(), 1e-12);
        assertEquals(2, cells.difference().high(), 1e-12);
        // six tied differences of +2: W+ = 21, mean 10.5, variance 6*7*13/24 - (6^3 - 6)/48 = 18.375;
        // z = (21 - 10.5 - 0.5) / sqrt(18.375) = 2.333, two-sided p = 0.0196 (continuity-corrected)
        assertEquals(0.0196, cells.pWilcoxon(), 1e-4);
        assertEquals(1.0, cells.a12(), 1e-12);
        assertEquals(EffectSize.LARGE, cells.effect());
        Comparison.MeasureTest maps = c.measures().stream()
                .filter(m -> m.measure() == Comparison.Measure.MAPS_RUN).findFirst().orElseThrow();
        assertEquals(1.0, maps.pWilcoxon(), 1e-12, "both ran three maps every time: no difference at all");
    }

    @Test
    void faultsFoundOnEveryMapOfOneDriverAndNoneOfTheOtherDifferAfterHolm() {
        Comparison c = Comparison.of(filterCoversAndFindsMore(), new SplittableRandom(3));
        Comparison.FaultTest f14 = c.faults().get(0);
        assertEquals(List.of(18L, 18L, 0L, 18L), List.of(f14.foundA(), f14.mapsA(), f14.foundB(), f14.mapsB()));
        // Fisher: only the observed table has that margin split, p = 2 / C(36,18) = 2.2e-10; Holm doubles it
        assertEquals(2 / 9075135300.0, f14.p(), 1e-15);
        assertEquals(2 * f14.p(), f14.pHolm(), 1e-15);
        // a zero cell: Haldane-Anscombe 0.5 in every cell, (18.5 * 18.5) / (0.5 * 0.5)
        assertEquals(1369, f14.oddsRatio(), 1e-9);
        Comparison.FaultTest f19 = c.faults().get(1);
        assertEquals(1, f19.p(), 1e-12);
        assertEquals(1, f19.pHolm(), 1e-12);
    }

    @Test
    void theSameSeedGivesTheSameIntervals() {
        Summary s = filterCoversAndFindsMore();
        assertEquals(Comparison.of(s, new SplittableRandom(9)).measures(), Comparison.of(s, new SplittableRandom(9)).measures());
        assertTrue(Comparison.of(s, new SplittableRandom(9)).measures().size() == Comparison.Measure.values().length);
    }
}
