package sitcov.oracle;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

class SquareGridTest {

    @Test
    void everySquareWithinReachOfAPointOnBothAxesIsNearItInSquareOrder() {
        SplittableRandom random = new SplittableRandom(5);
        int within = 0;
        for (int trial = 0; trial < 50; trial++) {
            int n = random.nextInt(1, 20);
            double[] xs = new double[n];
            double[] ys = new double[n];
            for (int j = 0; j < n; j++) {
                // junction centres sit on a coarse lattice in the maps
                xs[j] = 10 * random.nextInt(0, 30);
                ys[j] = 10 * random.nextInt(0, 30);
            }
            SquareGrid grid = new SquareGrid(xs, ys);
            for (int k = 0; k < 2000; k++) {
                int j0 = random.nextInt(n);
                // points just inside and just outside the reach of a square, and anywhere
                double x = k % 3 == 0 ? random.nextDouble(-20, 320)
                        : xs[j0] + (k % 2 == 0 ? 1 : -1) * Math.nextDown(SquareGrid.REACH) * random.nextDouble(0.9, 1);
                double y = k % 3 == 0 ? random.nextDouble(-20, 320) : ys[j0] + random.nextDouble(-SquareGrid.REACH, SquareGrid.REACH);
                int[] near = grid.near(x, y);
                for (int i = 1; i < near.length; i++) {
                    assertTrue(near[i] > near[i - 1], "square order");
                }
                for (int j = 0; j < n; j++) {
                    if (Math.abs(x - xs[j]) < SquareGrid.REACH && Math.abs(y - ys[j]) < SquareGrid.REACH) {
                        within++;
                        final int square = j;
                        assertTrue(java.util.Arrays.stream(near).anyMatch(s -> s == square),
                                "square " + j + " at (" + xs[j] + ", " + ys[j] + ") from (" + x + ", " + y + ")");
                    }
                }
            }
        }
        assertTrue(within > 10000, "points within reach were tried: " + within);
        assertEquals(0, new SquareGrid(new double[] {0}, new double[] {0}).near(Double.NaN, 0).length);
    }
}
