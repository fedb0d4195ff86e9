package sitcov.stats;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;

class NormalTest {
    @Test
    void cdfMatchesTheTabulatedNormalProbabilities() {
        // Abramowitz & Stegun (1964), Table 26.1: P(1) = 0.8413447461, P(2) = 0.9772498681;
        // the digits beyond the table cross-checked with scipy.stats.norm.cdf.
        assertEquals(0.8413447460685429, Normal.cdf(1), 1e-15);
        assertEquals(0.9772498680518208, Normal.cdf(2), 1e-15);
        assertEquals(0.5, Normal.cdf(0), 0);
        assertEquals(0.0013498980316300933, Normal.cdf(-3), 1e-17);
        assertEquals(0.975, Normal.cdf(1.959964), 1e-8);
    }

    @Test
    void theFarTailKeepsItsRelativeAccuracy() {
        // Q(10) = 7.61985302416047e-24 (scipy.stats.norm.sf(10), cross-checked); 1 - cdf(10) would be 0.
        assertEquals(7.61985302416047e-24, Normal.upperTail(10), 1e-36);
        assertEquals(1.0, Normal.cdf(40), 0);
        assertEquals(0.0, Normal.cdf(-40), 0);
    }

    @Test
    void quantileInvertsTheCdfToTheUsualCriticalValues() {
        // The familiar critical values 1.96 and 2.576 (Abramowitz & Stegun 1964, ch. 26) to full precision;
        // the digits cross-checked with scipy.stats.norm.ppf.
        assertEquals(1.959963984540054, Normal.quantile(0.975), 1e-12);
        assertEquals(-1.959963984540054, Normal.quantile(0.025), 1e-12);
        assertEquals(2.5758293035489004, Normal.quantile(0.995), 1e-12);
        assertEquals(0.0, Normal.quantile(0.5), 1e-15);
        assertEquals(-6.361340902404056, Normal.quantile(1e-10), 1e-10);
    }

    @Test
    void quantileAndCdfAreInversesAcrossTheRange() {
        for (double p = 0.0005; p < 1; p += 0.0005) {
            assertEquals(p, Normal.cdf(Normal.quantile(p)), 1e-14 + 1e-12 * p, "p = " + p);
        }
    }

    @Test
    void quantileOfTheEndsIsInfiniteAndOutsideIsRefused() {
        assertEquals(Double.NEGATIVE_INFINITY, Normal.quantile(0));
        assertEquals(Double.POSITIVE_INFINITY, Normal.quantile(1));
        assertThrows(IllegalArgumentException.class, () -> Normal.quantile(1.5));
    }
}
