package sitcov.estimate;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class EstimateReportTest {
    private static Estimate estimate(String method, int runs, long ticks, double rate, double halfWidth) {
        return new Estimate(method, new Failing.Any(), runs, ticks, 1, rate, rate - halfWidth, rate + halfWidth,
                halfWidth, runs);
    }

    @Test
    void halvingTheRelativeHalfWidthOnEqualTicksIsFourTimesFewerTicksAtEqualPrecision() {
        Estimate mc = estimate("mc", 1000, 100_000, 0.01, 0.002);
        Estimate is = estimate("is", 500, 100_000, 0.01, 0.001);
        assertEquals(4.0, EstimateReport.ticksRatio(mc, is), 1e-12);
        assertEquals(8.0, EstimateReport.runsRatio(mc, is), 1e-12);
    }

    @Test
    void estimatesAgreeWhenTheirDifferenceIsWithinItsInterval() {
        assertTrue(EstimateReport.agree(estimate("mc", 1, 1, 0.010, 0.002), estimate("is", 1, 1, 0.012, 0.002)));
        assertFalse(EstimateReport.agree(estimate("mc", 1, 1, 0.010, 0.001), estimate("is", 1, 1, 0.015, 0.001)));
    }
}
