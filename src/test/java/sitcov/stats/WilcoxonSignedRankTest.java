package sitcov.stats;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class WilcoxonSignedRankTest {
    @Test
    void signedRankMatchesTheDepressionScaleExampleOfRsDocumentation() {
        // Hollander & Wolfe (1973), p. 29f, as in R's ?wilcox.test: wilcox.test(x, y, paired = TRUE)
        // gives V = 40, p-value = 0.03906 (exact: 2 * 10 / 2^9 = 0.0390625).
        double[] x = {1.83, 0.50, 1.62, 2.48, 1.68, 1.88, 1.55, 3.06, 1.30};
        double[] y = {0.878, 0.647, 0.598, 2.05, 1.06, 1.29, 1.06, 3.14, 1.29};
        WilcoxonSignedRank.Result r = WilcoxonSignedRank.test(x, y);
        assertEquals(40, r.wPlus(), 0);
        assertEquals(9, r.n());
        assertTrue(r.exact());
        assertEquals(0.0390625, r.p(), 1e-15);
        assertEquals(r.p(), WilcoxonSignedRank.test(y, x).p(), 1e-15); // two-sided: symmetric
    }

    @Test
    void signedRankDropsTheZeroAndAveragesTiesInWikipediasExample() {
        // Wikipedia, "Wilcoxon signed-rank test", Example: 10 pairs, one zero difference dropped, so
        // N_r = 9 and the signed-rank sum W = 9, i.e. W+ = (W + 45) / 2 = 27. The two tied |differences|
        // force the normal approximation: z = 0.4743, p = 0.6353 (cross-checked with scipy.stats.wilcoxon
        // (zero_method="wilcox", correction=True, method="approx")).
        double[] after = {125, 115, 130, 140, 140, 115, 140, 125, 140, 135};
        double[] before = {110, 122, 125, 120, 140, 124, 123, 137, 135, 145};
        WilcoxonSignedRank.Result r = WilcoxonSignedRank.test(after, before);
        assertEquals(27, r.wPlus(), 0);
        assertEquals(9, r.n());
        assertEquals(9, 2 * r.wPlus() - r.n() * (r.n() + 1) / 2.0, 0);
        assertFalse(r.exact());
        assertEquals(0.4742953333830018, r.z(), 1e-12);
        assertEquals(0.6352893188352069, r.p(), 1e-12);
    }

    @Test
    void allZeroDifferencesLeaveNothingToRankAndPOne() {
        // Wilcoxon's convention: zero differences are dropped, so here n = 0 and nothing is evidence.
        WilcoxonSignedRank.Result r = WilcoxonSignedRank.test(new double[] {1, 2, 3}, new double[] {1, 2, 3});
        assertEquals(0, r.n());
        assertEquals(0, r.wPlus(), 0);
        assertEquals(1, r.p(), 0);
    }

    @Test
    void thirtyUntiedDifferencesOfOneSignGetTheExactP() {
        // all 30 positive: only the all-positive and the all-negative pattern are as extreme, p = 2 / 2^30
        double[] d = new double[30];
        for (int i = 0; i < d.length; i++) {
            d[i] = i + 1;
        }
        WilcoxonSignedRank.Result r = WilcoxonSignedRank.test(d);
        assertTrue(r.exact());
        assertEquals(465, r.wPlus(), 0);
        assertEquals(2 / Math.pow(2, 30), r.p(), 1e-24);
    }

    @Test
    void fiftyDifferencesUseTheNormalApproximation() {
        // 50 untied positive differences 1..50 (R is exact only below 50): W+ = 1275 = n(n+1)/2; by hand
        // z = (1275 - 637.5 - 0.5) / sqrt(50 * 51 * 101 / 24) = 637 / 103.5917 = 6.1491
        double[] d = new double[50];
        for (int i = 0; i < d.length; i++) {
            d[i] = i + 1;
        }
        WilcoxonSignedRank.Result r = WilcoxonSignedRank.test(d);
        assertFalse(r.exact());
        assertEquals(1275, r.wPlus(), 0);
        assertEquals(637 / Math.sqrt(50 * 51 * 101 / 24.0), r.z(), 1e-12);
        assertEquals(2 * Normal.cdf(-637 / Math.sqrt(50 * 51 * 101 / 24.0)), r.p(), 1e-20);
        assertTrue(r.p() < 1e-9);
    }

    @Test
    void theExactDistributionForThreeDifferencesIsTheOneOfTheTextbooks() {
        // n = 3: W+ takes 0, 1, 2, 3, 3, 4, 5, 6 over the 8 sign patterns (by hand), so W+ = 6 has
        // two-sided p = 2/8 and W+ = 3 has p = min(1, 2 * 5/8) = 1.
        assertEquals(0.25, WilcoxonSignedRank.exactP(6, 3, WilcoxonSignedRank.Alternative.TWO_SIDED), 1e-15);
        assertEquals(1, WilcoxonSignedRank.exactP(3, 3, WilcoxonSignedRank.Alternative.TWO_SIDED), 1e-15);
    }

    @Test
    void theOneSidedTestOfTheDepressionExampleHasRsPValue() {
        // R's ?wilcox.test: wilcox.test(x, y, paired = TRUE, alternative = "greater") gives V = 40, p-value =
        // 0.01953 (exact: 10 / 2^9 = 0.01953125)
        double[] x = {1.83, 0.50, 1.62, 2.48, 1.68, 1.88, 1.55, 3.06, 1.30};
        double[] y = {0.878, 0.647, 0.598, 2.05, 1.06, 1.29, 1.06, 3.14, 1.29};
        assertEquals(0.01953125, WilcoxonSignedRank.test(x, y, WilcoxonSignedRank.Alternative.GREATER).p(), 1e-15);
        // the other tail: P(W+ <= 40) = 1 - P(W+ >= 41) = 1 - 7/512 (the 3 subsets of 1..9 summing to 5 are the
        // patterns with W+ = 40), R's alternative = "less" p-value 0.9863
        assertEquals(505 / 512.0, WilcoxonSignedRank.test(x, y, WilcoxonSignedRank.Alternative.LESS).p(), 1e-15);
    }

    @Test
    void theSmallestAttainablePIsTwoInTwoToTheNTwoSided() {
        // all n untied differences of one sign: W+ = n(n+1)/2, reached by 1 of 2^n sign patterns
        for (int n : new int[] {5, 6, 10}) {
            double[] d = new double[n];
            for (int i = 0; i < n; i++) {
                d[i] = (i % 2 == 0 ? 1 : -1) * (i + 1.5);
            }
            assertEquals(2 / Math.pow(2, n), WilcoxonSignedRank.smallestP(d, WilcoxonSignedRank.Alternative.TWO_SIDED),
                    1e-15, "n=" + n);
            assertEquals(1 / Math.pow(2, n), WilcoxonSignedRank.smallestP(d, WilcoxonSignedRank.Alternative.GREATER),
                    1e-15, "n=" + n);
        }
        // so five paired replications cannot reach 0.05 two-sided (0.0625), six can (0.03125), ten reach 0.002
        assertEquals(0.0625, WilcoxonSignedRank.smallestP(new double[] {1, 2, 3, 4, 5}, WilcoxonSignedRank.Alternative.TWO_SIDED), 0);
        assertEquals(1, WilcoxonSignedRank.smallestP(new double[] {0, 0, 0}, WilcoxonSignedRank.Alternative.TWO_SIDED), 0);
    }
}
