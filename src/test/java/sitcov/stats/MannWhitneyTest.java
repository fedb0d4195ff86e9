package sitcov.stats;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import org.junit.jupiter.api.Test;

class MannWhitneyTest {
    @Test
    void mannWhitneyMatchesTheTortoiseAndHareExampleOfWikipedia() {
        // Wikipedia, "Mann-Whitney U test", Illustration of calculation methods: finishing order
        // T H H H H H T T T T T H gives U_T = 11 and U_H = 25. Finishing earlier is better, so
        // the speed of each runner is minus its place. Exact two-sided p = 2 * 143/924 = 0.3095
        // (cross-checked with scipy.stats.mannwhitneyu(method="exact")).
        double[] tortoises = {-1, -7, -8, -9, -10, -11};
        double[] hares = {-2, -3, -4, -5, -6, -12};
        MannWhitney.Result t = MannWhitney.test(tortoises, hares);
        assertEquals(11, t.u(), 0);
        assertEquals(25, MannWhitney.test(hares, tortoises).u(), 0);
        assertTrue(t.exact());
        assertTrue(Double.isNaN(t.z()));
        assertEquals(286.0 / 924, t.p(), 1e-12);
        assertEquals(t.p(), MannWhitney.test(hares, tortoises).p(), 1e-15);
    }

    @Test
    void mannWhitneyMatchesTheAmnionPermeabilityExampleOfHollanderAndWolfe() {
        // Hollander & Wolfe (1973), p. 69f, as in R's ?wilcox.test: wilcox.test(x, y, alternative = "g")
        // gives W = 35, p-value = 0.1272; the two-sided exact p is twice that, 0.2544 (cross-checked with
        // scipy: 0.2544122544).
        double[] x = {0.80, 0.83, 1.89, 1.04, 1.45, 1.38, 1.91, 1.64, 0.73, 1.46};
        double[] y = {1.15, 0.88, 0.90, 0.74, 1.21};
        MannWhitney.Result r = MannWhitney.test(x, y);
        assertEquals(35, r.u(), 0);
        assertTrue(r.exact());
        assertEquals(0.2544122544122544, r.p(), 1e-12);
    }

    @Test
    void tiedOzoneReadingsUseTheNormalApproximationAsInRsAirqualityExample() {
        // R's ?wilcox.test, formula interface: wilcox.test(Ozone ~ Month, data = airquality,
        // subset = Month %in% c(5, 8)) gives W = 127.5, p-value = 0.0001208 (ties, so the normal
        // approximation with tie and continuity corrections). The ozone readings of May and August
        // without the NAs; z = -3.8445 cross-checked by a hand-coded formula in Python.
        double[] may = {41, 36, 12, 18, 28, 23, 19, 8, 7, 16, 11, 14, 18, 14, 34, 6, 30, 11, 1, 11, 4, 32, 23,
            45, 115, 37};
        double[] august = {39, 9, 16, 78, 35, 66, 122, 89, 110, 44, 28, 65, 22, 59, 23, 31, 44, 21, 9, 45, 168,
            73, 76, 118, 84, 85};
        MannWhitney.Result r = MannWhitney.test(may, august);
        assertEquals(127.5, r.u(), 0);
        assertFalse(r.exact());
        assertEquals(-3.8444810272800702, r.z(), 1e-9);
        assertEquals(0.0001208, r.p(), 5e-8);
        assertEquals(0.00012080783076877434, r.p(), 1e-12); // scipy, use_continuity=True
    }

    @Test
    void largerUntiedSamplesThanTheExactLimitUseTheNormalApproximation() {
        // 21 against 21 values, all of the first sample below the second: U = 0; by hand,
        // z = (0 - 220.5 + 0.5) / sqrt(21 * 21 * 43 / 12) = -5.5343, p = 2 * Phi(-5.5343) = 3.1254e-8
        // (cross-checked with scipy.stats.mannwhitneyu(method="asymptotic")).
        double[] low = new double[21];
        double[] high = new double[21];
        for (int i = 0; i < 21; i++) {
            low[i] = i;
            high[i] = 100 + i;
        }
        MannWhitney.Result r = MannWhitney.test(low, high);
        assertFalse(r.exact());
        assertEquals(0, r.u(), 0);
        assertEquals(-220 / Math.sqrt(21 * 21 * 43 / 12.0), r.z(), 1e-12);
        assertEquals(3.125399998400872e-08, r.p(), 1e-18);
    }

    @Test
    void exactCountsAreTheGaussianBinomialCoefficients() {
        // For m = n = 2 the C(4, 2) = 6 arrangements give U = 0, 1, 2, 2, 3, 4 (by hand),
        // and all counts for m = n = 20 sum to C(40, 20) = 137846528820.
        assertArrayEquals(new long[] {1, 1, 2, 1, 1}, MannWhitney.uCounts(2, 2));
        assertEquals(137_846_528_820L, Arrays.stream(MannWhitney.uCounts(20, 20)).sum());
    }

    @Test
    void anEmptySampleGivesNoTestRatherThanAnError() {
        MannWhitney.Result r = MannWhitney.test(new double[0], new double[] {1, 2, 3});
        assertTrue(Double.isNaN(r.p()));
        assertTrue(Double.isNaN(r.u()));
        assertFalse(r.exact());
    }
}
