package sitcov.stats;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class FisherExactTest {
    @Test
    void fisherMatchesTheLadyTastingTea() {
        // Fisher (1935), The Design of Experiments, ch. II; R's ?fisher.test TeaTasting example. With
        // margins 4/4 the tables a = 0..4 have probabilities 1, 16, 36, 16, 1 out of 70, so the two-sided
        // p of a = 3 is 34/70 = 0.4857. (R's odds ratio there is the conditional MLE 6.41; ours is the
        // sample one, 3 * 3 / (1 * 1) = 9, with Woolf's interval exp(ln 9 +- 1.96 * sqrt(8/3)) =
        // 0.3666..220.9 by hand.)
        FisherExact.Result r = FisherExact.test(3, 1, 1, 3);
        assertEquals(34.0 / 70, r.p(), 1e-12);
        assertEquals(9, r.oddsRatio(), 1e-12);
        assertEquals(0.36663693192554553, r.low(), 1e-12);
        assertEquals(220.92700692915736, r.high(), 1e-9);
        assertFalse(r.corrected());
    }

    @Test
    void fisherMatchesWikipediasDietingExample() {
        // Wikipedia, "Fisher's exact test", Example: men/women dieting [[1, 9], [11, 3]] has two-sided
        // p = 0.002759 (cross-checked with scipy.stats.fisher_exact: 0.0027594561852200836).
        assertEquals(0.0027594561852200836, FisherExact.twoSidedP(1, 9, 11, 3), 1e-15);
        assertEquals(FisherExact.twoSidedP(1, 9, 11, 3), FisherExact.twoSidedP(9, 1, 3, 11), 1e-15);
    }

    @Test
    void fisherMatchesTheConvictionsOfTwinsInRsDocumentation() {
        // R's ?fisher.test Convictions example (Fisher 1962, twins of criminals): [[2, 10], [15, 3]],
        // one-sided "less" p = 0.0004652 in R; our two-sided p 0.0005367241 was cross-checked with scipy.
        assertEquals(0.0005367241191434357, FisherExact.twoSidedP(2, 10, 15, 3), 1e-15);
    }

    @Test
    void oddsRatioAndWoolfIntervalMatchBlandAndAltmansHayFeverExample() {
        // Bland & Altman (2000), "The odds ratio", BMJ 320:1468: eczema and hay fever in 15 522 children,
        // [[141, 420], [928, 13525]], OR = 4.89, 95 % CI 4.00 to 5.99 (SE of ln OR 0.103; recomputed by
        // hand: 3.998 to 5.988). The p-value 2.5875e-42 (scipy) shows the log-factorial path is stable.
        FisherExact.Result r = FisherExact.test(141, 420, 928, 13525);
        assertEquals(4.89, r.oddsRatio(), 0.005);
        assertEquals(4.00, r.low(), 0.005);
        assertEquals(5.99, r.high(), 0.005);
        assertEquals(2.587538511760508e-42, r.p(), 1e-47);
        assertFalse(r.corrected());
    }

    @Test
    void aZeroCellAddsOneHalfToEveryCellBeforeTheOddsRatio() {
        // Haldane-Anscombe by hand: [[0, 5], [5, 5]] becomes [[0.5, 5.5], [5.5, 5.5]], OR = 1/11,
        // SE = sqrt(2 + 3/5.5) = 1.5954, CI 0.003986..2.0733. Fisher's p = 0.1009 (scipy).
        FisherExact.Result r = FisherExact.test(0, 5, 5, 5);
        assertTrue(r.corrected());
        assertEquals(1.0 / 11, r.oddsRatio(), 1e-12);
        assertEquals(0.0039862033993565815, r.low(), 1e-12);
        assertEquals(2.073266710688001, r.high(), 1e-9);
        assertEquals(0.1008991008991009, r.p(), 1e-12);
    }

    @Test
    void logFactorialsAgreeWithLgammaOnBothSidesOfTheTable() {
        // ln Gamma(n + 1) from Python's math.lgamma: 100! in the table, 1024! and 2000! by Stirling's series.
        assertEquals(363.73937555556347, LogFactorial.of(100), 1e-10);
        assertEquals(6078.211884750051, LogFactorial.of(1024), 1e-9);
        assertEquals(13206.524350513806, LogFactorial.of(2000), 1e-9);
        assertEquals(Math.log(1024), LogFactorial.of(1024) - LogFactorial.of(1023), 1e-10);
    }
}
