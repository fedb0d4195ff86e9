package sitcov.analysis;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

class SweepTest {
    @Test
    void pointsOnALineFitItExactlyWithRSquaredOne() {
        assertArrayEquals(new double[] {1, 0.5, 1}, Sweep.regression(new double[] {0, 2, 4}, new double[] {1, 2, 3}), 1e-12);
    }

    @Test
    void rSquaredOfAScatterIsTheSquaredCorrelationWorkedByHand() {
        // x = 1,2,3,4  y = 2,1,4,3: mean 2.5 each, sxy = 3, sxx = syy = 5, so b = 0.6, a = 1, r2 = 9/25
        double[] fit = Sweep.regression(new double[] {1, 2, 3, 4}, new double[] {2, 1, 4, 3});
        assertEquals(1.0, fit[0], 1e-12);
        assertEquals(0.6, fit[1], 1e-12);
        assertEquals(0.36, fit[2], 1e-12);
    }

    @Test
    void aFlatCloudHasNoSlopeAndNoFit() {
        assertArrayEquals(new double[] {2, 0, 0}, Sweep.regression(new double[] {1, 2, 3}, new double[] {2, 2, 2}), 1e-12);
    }
}
