package sitcov.stats;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

class DescriptiveTest {
    @Test
    void quartilesOfOneToTenFollowDefinitionSevenLikeRsQuantile() {
        // Hyndman & Fan (1996) definition 7, h = (n-1)p + 1: for 1..10 the quartiles are 3.25, 5.5, 7.75
        // (by hand; R's quantile(1:10) and numpy.quantile give the same).
        double[] x = {10, 1, 9, 2, 8, 3, 7, 4, 6, 5};
        Descriptive.Quartiles q = Descriptive.quartiles(x);
        assertEquals(3.25, q.lower(), 1e-12);
        assertEquals(5.5, q.median(), 1e-12);
        assertEquals(7.75, q.upper(), 1e-12);
        assertEquals(4.5, q.iqr(), 1e-12);
    }

    @Test
    void quantilesInterpolateBetweenOrderStatistics() {
        // Definition 7 by hand on 2, 4, 4, 5, 7, 9, 10, 12: positions 2.75, 4.5, 6.25 give 4, 6, 9.25
        // (cross-checked with numpy.quantile).
        double[] x = {12, 2, 9, 4, 7, 5, 10, 4};
        assertEquals(4, Descriptive.quantile(x, 0.25), 1e-12);
        assertEquals(6, Descriptive.median(x), 1e-12);
        assertEquals(9.25, Descriptive.quantile(x, 0.75), 1e-12);
        assertEquals(2, Descriptive.quantile(x, 0), 0);
        assertEquals(12, Descriptive.quantile(x, 1), 0);
    }

    @Test
    void meanAndVarianceOfTheMouseTreatmentGroupMatchEfronAndTibshirani() {
        // Efron & Tibshirani, An Introduction to the Bootstrap (1993), Table 2.1: treatment group
        // mean 86.86 with estimated standard error 25.24 = sqrt(variance / 7).
        double[] treatment = {94, 197, 16, 38, 99, 141, 23};
        assertEquals(86.86, Descriptive.mean(treatment), 0.005);
        assertEquals(25.24, Math.sqrt(Descriptive.variance(treatment) / treatment.length), 0.005);
    }
}
