package sitcov.stats;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;

import org.junit.jupiter.api.Test;

class HolmTest {
    @Test
    void holmMatchesWikipediasFourHypothesisExample() {
        // Wikipedia, "Holm-Bonferroni method", Example: p = 0.01, 0.04, 0.03, 0.005 at alpha = 0.05
        // rejects H1 and H4 only. Adjusted (by hand; R's p.adjust(c(0.01, 0.04, 0.03, 0.005), "holm")):
        // 0.03, 0.06, 0.06, 0.02 - the 0.04 is lifted to 0.06 by monotonicity.
        double[] adjusted = Holm.adjust(0.01, 0.04, 0.03, 0.005);
        assertArrayEquals(new double[] {0.03, 0.06, 0.06, 0.02}, adjusted, 1e-15);
        boolean[] rejected = new boolean[adjusted.length];
        for (int i = 0; i < adjusted.length; i++) {
            rejected[i] = adjusted[i] <= 0.05;
        }
        assertArrayEquals(new boolean[] {true, false, false, true}, rejected);
    }

    @Test
    void adjustedValuesAreCappedAtOneAndStayMonotone() {
        // By hand: sorted 0.2, 0.5, 0.6 times 3, 2, 1 gives 0.6, 1.0, 0.6, then the running maximum.
        assertArrayEquals(new double[] {1, 0.6, 1}, Holm.adjust(0.5, 0.2, 0.6), 1e-15);
        assertArrayEquals(new double[0], Holm.adjust());
    }
}
