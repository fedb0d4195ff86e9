package sitcov.stats;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class DetectableDifferenceTest {
    @Test
    void thirtyPairsOfUnitSpreadDetectAboutHalfAUnit() {
        // (t_0.975,29 + t_0.80,29) / sqrt(30) = (2.045 + 0.854) / 5.4772 = 0.5293 (table quantiles)
        assertEquals(0.5293, DetectableDifference.pairedT(1, 30, 0.05, true, 0.8), 5e-4);
        // one-sided puts the whole 5 % in one tail: (1.699 + 0.854) / 5.4772 = 0.4661
        assertEquals(0.4661, DetectableDifference.pairedT(1, 30, 0.05, false, 0.8), 5e-4);
    }

    @Test
    void aStricterLevelOrFewerPairsNeedALargerDifference() {
        double base = DetectableDifference.pairedT(2, 30, 0.05, true, 0.8);
        assertTrue(DetectableDifference.pairedT(2, 30, 0.05 / 100, true, 0.8) > base);
        assertTrue(DetectableDifference.pairedT(2, 10, 0.05, true, 0.8) > base);
        assertEquals(2 * DetectableDifference.pairedT(1, 30, 0.05, true, 0.8), base, 1e-12, "it scales with the spread");
    }
}
