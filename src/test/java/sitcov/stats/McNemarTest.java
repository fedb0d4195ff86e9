package sitcov.stats;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;

class McNemarTest {
    @Test
    void fiveDiscordantPairsAllOneWayGiveTwiceOneIn32() {
        // P(X <= 0) for X ~ Bin(5, 1/2) is 1/32; two-sided doubles it
        assertEquals(2.0 / 32, McNemar.exactP(0, 5), 1e-12);
        assertEquals(2.0 / 32, McNemar.exactP(5, 0), 1e-12);
    }

    @Test
    void twoAgainstEightSumsTheLowerTailOfBinomialTen() {
        // P(X <= 2) for Bin(10, 1/2) = (1 + 10 + 45) / 1024
        assertEquals(2 * 56.0 / 1024, McNemar.exactP(2, 8), 1e-12);
    }

    @Test
    void anEvenSplitOrNoDiscordantPairIsNoEvidence() {
        assertEquals(1.0, McNemar.exactP(4, 4), 1e-12);
        assertEquals(1.0, McNemar.exactP(0, 0), 1e-12);
    }

    @Test
    void sevenAgainstOneGivesTheTailOfBinomialEight() {
        // P(X <= 1) for Bin(8, 1/2) = (1 + 8) / 256; two-sided 18 / 256 = 0.0703
        assertEquals(0.0703125, McNemar.exactP(7, 1), 1e-12);
    }

    @Test
    void fewerThanSixDiscordantPairsCannotReachFivePercent() {
        assertEquals(0.0625, McNemar.smallestP(5), 1e-12);
        assertEquals(0.03125, McNemar.smallestP(6), 1e-12);
        assertEquals(1.0, McNemar.smallestP(0), 1e-12);
    }

    @Test
    void negativeCountsAreRefused() {
        assertThrows(IllegalArgumentException.class, () -> McNemar.exactP(-1, 3));
    }
}
