package sitcov.stats;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class DispersionTest {
    @Test
    void samplesAtThePooledProportionShowNoExtraVariation() {
        assertEquals(0, Dispersion.pearson(new long[] {5, 5, 5}, new long[] {10, 10, 10}), 1e-15);
    }

    @Test
    void allSuccessesInOneSampleAreOverDispersed() {
        // by hand: p = 10/20, each sample expects 5 with variance 2.5; X^2 = 25/2.5 + 25/2.5 = 20 over 1 df
        assertEquals(20, Dispersion.pearson(new long[] {10, 0}, new long[] {10, 10}), 1e-12);
        // three samples 6/20, 0/20, 0/20: p = 0.1, expected 2 each, variance 1.8:
        // X^2 = (16 + 4 + 4) / 1.8 = 13.33 over 2 df
        assertEquals(24 / 1.8 / 2, Dispersion.pearson(new long[] {6, 0, 0}, new long[] {20, 20, 20}), 1e-12);
    }

    @Test
    void nothingFoundOrFewerThanTwoSamplesHaveNoDispersion() {
        assertTrue(Double.isNaN(Dispersion.pearson(new long[] {0, 0}, new long[] {10, 10})));
        assertTrue(Double.isNaN(Dispersion.pearson(new long[] {3}, new long[] {10})));
        assertTrue(Double.isNaN(Dispersion.pearson(new long[] {10, 10}, new long[] {10, 10})));
    }
}
