package sitcov.stats;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class WilsonTest {
    // Newcombe (1998), Statistics in Medicine 17:857, worked examples for method 3 (score interval
    // without continuity correction), given to four decimals; each also recomputed from the formula
    // in Python with scipy's z = 1.959963984540054.
    private static final double FOUR_DECIMALS = 5e-5;

    @Test
    void wilsonMatchesNewcombesEightyOneOfTwoHundredSixtyThree() {
        ConfidenceInterval ci = Wilson.interval(81, 263);
        assertEquals(0.2553, ci.low(), FOUR_DECIMALS);
        assertEquals(0.3662, ci.high(), FOUR_DECIMALS);
        assertEquals(81.0 / 263, ci.estimate(), 1e-15);
    }

    @Test
    void wilsonMatchesNewcombesFifteenOfOneHundredFortyEight() {
        ConfidenceInterval ci = Wilson.interval(15, 148);
        assertEquals(0.0624, ci.low(), FOUR_DECIMALS);
        assertEquals(0.1605, ci.high(), FOUR_DECIMALS);
    }

    @Test
    void wilsonMatchesNewcombesNoneOfTwentyAndOneOfTwentynine() {
        ConfidenceInterval none = Wilson.interval(0, 20);
        assertEquals(0, none.low(), 0);
        assertEquals(0.1611, none.high(), FOUR_DECIMALS);
        ConfidenceInterval one = Wilson.interval(1, 29);
        assertEquals(0.0061, one.low(), FOUR_DECIMALS);
        assertEquals(0.1718, one.high(), FOUR_DECIMALS);
    }

    @Test
    void allSuccessesMirrorNoSuccessesAndNoTrialsGiveTheWholeUnitInterval() {
        // The score interval is symmetric under k -> n - k (Wilson 1927): 20/20 is 1 - (0/20).
        ConfidenceInterval all = Wilson.interval(20, 20);
        assertEquals(1 - 0.1611, all.low(), FOUR_DECIMALS);
        assertEquals(1, all.high(), 0);
        ConfidenceInterval nothing = Wilson.interval(0, 0);
        assertEquals(0, nothing.low(), 0);
        assertEquals(1, nothing.high(), 0);
        assertTrue(Double.isNaN(nothing.estimate()));
    }

    @Test
    void aGivenZEqualsTheMatchingConfidence() {
        // z = 1.959963984540054 is the 97.5 % normal quantile, so both calls describe the same interval.
        ConfidenceInterval byZ = Wilson.intervalForZ(81, 263, 1.959963984540054);
        ConfidenceInterval byConfidence = Wilson.interval(81, 263, 0.95);
        assertEquals(byZ.low(), byConfidence.low(), 1e-14);
        assertEquals(byZ.high(), byConfidence.high(), 1e-14);
        assertEquals(0.2552885198782742, byZ.low(), 1e-12);
        assertEquals(0.36620957698280004, byZ.high(), 1e-12);
    }
}
