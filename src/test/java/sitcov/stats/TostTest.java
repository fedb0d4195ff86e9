package sitcov.stats;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class TostTest {
    @Test
    void thePairedExampleOfLakensPrimerGivesItsPublishedTests() {
        // Lakens 2017, "Equivalence tests: a practical primer for t tests, correlations, and meta-analyses",
        // Social Psychological and Personality Science 8:355, its paired example as TOSTER's known-results test
        // keeps it: TOSTpaired.raw(n = 65, m1 = 5.83, m2 = 5.75, sd1 = 1.17, sd2 = 1.30, r12 = 0.745, bounds
        // -0.34 and 0.34) gives t1 = 3.803437, p1 = 0.0001606103, t2 = -2.354508, p2 = 0.01081349 and the 90 %
        // interval -0.1043032 to 0.2643032. The paired differences' sd is sqrt(sd1^2 + sd2^2 - 2 r sd1 sd2).
        double sd = Math.sqrt(1.17 * 1.17 + 1.30 * 1.30 - 2 * 0.745 * 1.17 * 1.30);
        Tost.Result r = Tost.ofSummary(5.83 - 5.75, sd, 65, 0.34, 0.05);
        assertEquals(0.0001606103, r.pLower(), 1e-9);
        assertEquals(0.01081349, r.pUpper(), 1e-7);
        assertEquals(0.01081349, r.p(), 1e-7);
        assertEquals(-0.1043032, r.low(), 1e-6);
        assertEquals(0.2643032, r.high(), 1e-6);
        assertTrue(r.equivalent(0.05));
        assertFalse(r.equivalent(0.01));
    }

    @Test
    void theOneSampleExampleOfTosterGivesItsPublishedTests() {
        // TOSTER's known results: TOSTone.raw(m = 0.52, mu = 0.5, sd = 0.5, n = 300, bounds -0.1 and 0.1) gives
        // p1 = 0.00002108451, p2 = 0.002966762, 90 % interval -0.02763041 to 0.06763041 (around m - mu)
        Tost.Result r = Tost.ofSummary(0.52 - 0.5, 0.5, 300, 0.1, 0.05);
        assertEquals(0.00002108451, r.pLower(), 1e-10);
        assertEquals(0.002966762, r.pUpper(), 1e-8);
        assertEquals(-0.02763041, r.low(), 1e-7);
        assertEquals(0.06763041, r.high(), 1e-7);
    }

    @Test
    void differencesAllAlikeGiveNoTestAndNoClaim() {
        Tost.Result same = Tost.paired(new double[] {3, 4, 5}, new double[] {3, 4, 5}, 1, 0.05);
        assertTrue(Double.isNaN(same.p()));
        assertFalse(same.equivalent(0.05));
        assertTrue(Double.isNaN(Tost.paired(new double[] {5, 6, 7}, new double[] {3, 4, 5}, 1, 0.05).p()));
    }

    @Test
    void aMeanFarOutsideTheMarginIsNotEquivalent() {
        Tost.Result r = Tost.ofDifferences(new double[] {95, 96, 97, 98, 96}, 5, 0.05);
        assertTrue(r.p() > 0.99, "p=" + r.p());
    }

    @Test
    void fewerThanTwoPairsGiveNoTestAndNoInterval() {
        Tost.Result none = Tost.ofDifferences(new double[0], 1, 0.05);
        assertTrue(Double.isNaN(none.p()) && Double.isNaN(none.low()) && Double.isNaN(none.high()));
        assertTrue(Double.isNaN(none.mean()));
        Tost.Result one = Tost.paired(new double[] {4}, new double[] {3}, 1, 0.05);
        assertEquals(1, one.mean(), 0);
        assertTrue(Double.isNaN(one.p()) && Double.isNaN(one.low()), "one pair has no spread to test with");
        assertFalse(one.equivalent(0.05));
    }
}
