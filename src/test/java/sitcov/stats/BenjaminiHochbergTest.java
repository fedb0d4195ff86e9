package sitcov.stats;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;

class BenjaminiHochbergTest {
    @Test
    void theFifteenTestsOfBenjaminiAndHochbergs1995ExampleGiveFourDiscoveries() {
        // Benjamini & Hochberg 1995, section 4.1: at q = 0.05 the four smallest are rejected; the fifth,
        // 0.0201, would need 0.0201 <= 5 × 0.05 / 15 = 0.0167 and no later p under its own bound
        double[] p = {0.0001, 0.0004, 0.0019, 0.0095, 0.0201, 0.0278, 0.0298, 0.0344, 0.0459, 0.3240, 0.4262, 0.5719,
            0.6528, 0.7590, 1.0000};
        assertEquals(4, BenjaminiHochberg.discoveries(0.05, p));
        double[] q = BenjaminiHochberg.adjust(p);
        // by hand: 4th 0.0095 × 15 / 4 = 0.035625; 5th min(0.0201 × 3, 0.0278 × 15/6, 0.0298 × 15/7, ...) = 0.0603
        assertEquals(0.035625, q[3], 1e-12);
        assertEquals(0.0603, q[4], 1e-12);
        assertEquals(0.0015, q[0], 1e-12, "0.0001 × 15, below the 0.003 (0.0004 × 15 / 2) above it");
        assertEquals(1.0, q[14], 0);
    }

    @Test
    void adjustsInTheOrderGivenAndCapsAtOne() {
        // sorted 0.005, 0.01, 0.03, 0.04 (m = 4): 0.02, 0.02, 0.04, 0.04, then the running minimum from the top
        assertArrayEquals(new double[] {0.02, 0.04, 0.04, 0.02}, BenjaminiHochberg.adjust(0.01, 0.04, 0.03, 0.005), 1e-15);
        assertArrayEquals(new double[] {0.6, 0.6, 0.6}, BenjaminiHochberg.adjust(0.5, 0.2, 0.6), 1e-15);
        assertArrayEquals(new double[0], BenjaminiHochberg.adjust());
        assertThrows(IllegalArgumentException.class, () -> BenjaminiHochberg.adjust(Double.NaN));
    }
}
