package sitcov.stats;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

class ClosedTestingTest {
    private static final double NA = Double.NaN;

    @Test
    void aPlaceOfTwoDisjointHypothesesCostsTheFamilyOneTest() {
        // places A (0.01, 0.5), B (0.02, none), C (0.6, 0.001); by hand:
        // A's 0.01 beside B's 0.02 and C's larger 0.6: Holm of (0.01, 0.02, 0.6) gives 0.03 for it
        // B's 0.02 beside A's 0.5 and C's 0.6: 0.06, 1.0 lifted... sorted 0.02, 0.5, 0.6 gives 0.06
        // C's 0.001 beside A's 0.5 and B's 0.02: sorted 0.001, 0.02, 0.5 gives 0.003
        double[][] adjusted = ClosedTesting.adjust(new double[][] {{0.01, 0.5}, {0.02, NA}, {0.6, 0.001}});
        assertEquals(0.03, adjusted[0][0], 1e-15);
        assertEquals(0.06, adjusted[1][0], 1e-15);
        assertEquals(0.003, adjusted[2][1], 1e-15);
        assertEquals(1.0, adjusted[0][1], 1e-15, "A's 0.5 beside 0.02 and 0.6: 0.02 × 3, 0.5 × 2 = 1.0");
        assertEquals(NA, adjusted[1][1]);
    }

    @Test
    void withOneHypothesisAPlaceItIsHolm() {
        double[][] adjusted = ClosedTesting.adjust(new double[][] {{0.01}, {0.04}, {0.03}, {0.005}});
        double[] holm = Holm.adjust(0.01, 0.04, 0.03, 0.005);
        for (int j = 0; j < holm.length; j++) {
            assertEquals(holm[j], adjusted[j][0], 1e-15);
        }
    }

    @Test
    void theShortcutRejectsWhatTheFullClosureWithBonferroniLocalTestsRejects() {
        // the closure enumerated: every intersection holding h and at most one hypothesis of each other place
        // (two of one place is empty) must have min p <= alpha / its size
        SplittableRandom random = new SplittableRandom(11);
        for (int trial = 0; trial < 300; trial++) {
            int places = 1 + random.nextInt(5);
            double[][] p = new double[places][2];
            for (double[] place : p) {
                place[0] = Math.pow(random.nextDouble(), 3);
                place[1] = random.nextInt(3) == 0 ? NA : Math.pow(random.nextDouble(), 3);
            }
            double[][] adjusted = ClosedTesting.adjust(p);
            for (double alpha : new double[] {0.01, 0.05, 0.1}) {
                for (int j = 0; j < places; j++) {
                    for (int k = 0; k < 2; k++) {
                        if (!Double.isNaN(p[j][k])) {
                            assertEquals(closureRejects(p, j, k, alpha), adjusted[j][k] <= alpha, "trial " + trial);
                        }
                    }
                }
            }
        }
    }

    private static boolean closureRejects(double[][] p, int j, int k, double alpha) {
        List<Integer> others = new ArrayList<>();
        for (int i = 0; i < p.length; i++) {
            if (i != j) {
                others.add(i);
            }
        }
        // each other place: left out (0), its first (1) or its second hypothesis (2)
        int combinations = (int) Math.pow(3, others.size());
        for (int c = 0; c < combinations; c++) {
            double min = p[j][k];
            int size = 1;
            int code = c;
            boolean valid = true;
            for (int i : others) {
                int pick = code % 3;
                code /= 3;
                if (pick > 0) {
                    double v = p[i][pick - 1];
                    if (Double.isNaN(v)) {
                        valid = false;
                        break;
                    }
                    min = Math.min(min, v);
                    size++;
                }
            }
            if (valid && min > alpha / size) {
                return false;
            }
        }
        return true;
    }

    @Test
    void anEmptyFamilyIsEmpty() {
        assertArrayEquals(new double[0][], ClosedTesting.adjust(new double[0][]));
    }
}
