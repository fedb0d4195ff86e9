package sitcov.stats;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class RanksTest {
    @Test
    void tiedAbsoluteDifferencesShareTheirAverageRankAsInWikipediasSignedRankExample() {
        // Wikipedia, "Wilcoxon signed-rank test", Example: the nine non-zero |differences|
        // 15, 7, 5, 20, 9, 17, 12, 5, 10 get ranks 7, 3, 1.5, 9, 4, 8, 6, 1.5, 5.
        double[] magnitudes = {15, 7, 5, 20, 9, 17, 12, 5, 10};
        assertArrayEquals(new double[] {7, 3, 1.5, 9, 4, 8, 6, 1.5, 5}, Ranks.average(magnitudes), 0);
        assertEquals(6, Ranks.tieTerm(magnitudes), 0); // one pair: 2^3 - 2
        assertTrue(Ranks.hasTies(magnitudes));
    }

    @Test
    void aThreeWayTieSpansThreeRanksAndCountsTwentyfourInTheTieTerm() {
        // By hand: 3 tied values at positions 2..4 share rank 3; t^3 - t = 24.
        double[] values = {9, 4, 4, 1, 4};
        assertArrayEquals(new double[] {5, 3, 3, 1, 3}, Ranks.average(values), 0);
        assertEquals(24, Ranks.tieTerm(values), 0);
        assertFalse(Ranks.hasTies(new double[] {3, 1, 2}));
    }
}
