package sitcov.stats;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

class RichnessTest {
    @Test
    void chao1OfTenSingletonsAndFiveDoubletonsInAHundredIsNinePointNine() {
        // (n-1)/n * f1^2 / (2 f2) = 0.99 * 100 / 10, by hand
        assertEquals(9.9, Richness.unseen(100, 10, 5), 1e-12);
    }

    @Test
    void withoutDoubletonsChao1UsesTheBiasCorrectedForm() {
        // (n-1)/n * f1 (f1 - 1) / 2 = 0.9 * 3 * 2 / 2
        assertEquals(2.7, Richness.unseen(10, 3, 0), 1e-12);
    }

    @Test
    void aHundredMoreDrawsFindAboutSixOfTheNinePointNineUnseenKinds() {
        // f0 (1 - (1 - f1 / (n f0 + f1))^m) = 9.9 (1 - 0.99^100) = 9.9 * 0.633968 by hand
        assertEquals(9.9 * (1 - Math.pow(0.99, 100)), Richness.expectedNew(100, 10, 5, 100), 1e-12);
        assertEquals(6.2763, Richness.expectedNew(100, 10, 5, 100), 1e-4);
    }

    @Test
    void noSingletonsMeansNothingNewAndEndlessDrawsFindEveryUnseenKind() {
        assertEquals(0, Richness.expectedNew(100, 0, 7, 1000), 0);
        assertEquals(9.9, Richness.expectedNew(100, 10, 5, 1_000_000), 1e-9);
    }
}
