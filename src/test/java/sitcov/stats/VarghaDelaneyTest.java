package sitcov.stats;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class VarghaDelaneyTest {
    @Test
    void a12CountsWinsAndHalfTiesOnATinySampleByHand() {
        // By the definition: 1 beats none of 2, 2, 4; 2 ties twice; 3 beats 2 and 2.
        // A12 = (0 + 0.5 + 0.5 + 1 + 1) / 9 = 3/9, and A21 = 1 - A12.
        double[] x = {1, 2, 3};
        double[] y = {2, 2, 4};
        assertEquals(3.0 / 9, VarghaDelaney.a12(x, y), 1e-15);
        assertEquals(6.0 / 9, VarghaDelaney.a12(y, x), 1e-15);
        assertEquals(EffectSize.MEDIUM, VarghaDelaney.magnitude(VarghaDelaney.a12(x, y)));
    }

    @Test
    void a12IsUOverMnOnHollanderAndWolfesPermeabilityData() {
        // Vargha & Delaney (2000): A12 = U1 / (m n). Hollander & Wolfe (1973) p. 69f (R's ?wilcox.test):
        // W = U = 35 with m = 10, n = 5, so A12 = 0.7, a medium effect (0.64 <= 0.7 < 0.71).
        double[] x = {0.80, 0.83, 1.89, 1.04, 1.45, 1.38, 1.91, 1.64, 0.73, 1.46};
        double[] y = {1.15, 0.88, 0.90, 0.74, 1.21};
        double a12 = VarghaDelaney.a12(x, y);
        assertEquals(0.7, a12, 1e-15);
        assertEquals(MannWhitney.test(x, y).u() / (x.length * y.length), a12, 1e-15);
        assertEquals(EffectSize.MEDIUM, VarghaDelaney.magnitude(a12));
    }

    @Test
    void a12IsUOverMnWithTiesOnRsAirqualityData() {
        // R's ?wilcox.test airquality example: W = 127.5 for 26 May against 26 August ozone readings, so
        // A12 = 127.5 / 676 = 0.1886, a large effect (below 0.29).
        double[] may = {41, 36, 12, 18, 28, 23, 19, 8, 7, 16, 11, 14, 18, 14, 34, 6, 30, 11, 1, 11, 4, 32, 23,
            45, 115, 37};
        double[] august = {39, 9, 16, 78, 35, 66, 122, 89, 110, 44, 28, 65, 22, 59, 23, 31, 44, 21, 9, 45, 168,
            73, 76, 118, 84, 85};
        assertEquals(127.5 / 676, VarghaDelaney.a12(may, august), 1e-15);
        assertEquals(EffectSize.LARGE, VarghaDelaney.magnitude(VarghaDelaney.a12(may, august)));
    }

    @Test
    void magnitudesFollowVarghaAndDelaneysThresholdsSymmetricallyAboutOneHalf() {
        // Vargha & Delaney (2000): small 0.56, medium 0.64, large 0.71, mirrored at 0.44, 0.36, 0.29.
        assertEquals(EffectSize.NEGLIGIBLE, VarghaDelaney.magnitude(0.5));
        assertEquals(EffectSize.NEGLIGIBLE, VarghaDelaney.magnitude(0.5599));
        assertEquals(EffectSize.NEGLIGIBLE, VarghaDelaney.magnitude(0.4401));
        assertEquals(EffectSize.SMALL, VarghaDelaney.magnitude(0.56));
        assertEquals(EffectSize.SMALL, VarghaDelaney.magnitude(44 / 100.0));
        assertEquals(EffectSize.SMALL, VarghaDelaney.magnitude(0.6399));
        assertEquals(EffectSize.MEDIUM, VarghaDelaney.magnitude(0.64));
        assertEquals(EffectSize.MEDIUM, VarghaDelaney.magnitude(0.36));
        assertEquals(EffectSize.MEDIUM, VarghaDelaney.magnitude(0.7099));
        assertEquals(EffectSize.LARGE, VarghaDelaney.magnitude(0.71));
        assertEquals(EffectSize.LARGE, VarghaDelaney.magnitude(0.29));
        assertEquals(EffectSize.LARGE, VarghaDelaney.magnitude(0));
    }

    @Test
    void labelsAreLowerCase() {
        assertEquals("negligible", EffectSize.NEGLIGIBLE.label());
        assertEquals("large", EffectSize.LARGE.label());
    }

    @Test
    void anEmptySampleHasNoA12AndItsMagnitudeIsUndefined() {
        // no pair to count: a shard with no replications still gets its tables, with nothing claimed
        assertTrue(Double.isNaN(VarghaDelaney.a12(new double[0], new double[] {1, 2})));
        assertTrue(Double.isNaN(VarghaDelaney.a12(new double[] {1}, new double[0])));
        assertEquals(EffectSize.UNDEFINED, VarghaDelaney.magnitude(Double.NaN));
        assertEquals("undefined", EffectSize.UNDEFINED.label());
        assertThrows(IllegalArgumentException.class, () -> VarghaDelaney.magnitude(1.5), "out of range is still refused");
    }
}
