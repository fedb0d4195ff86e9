package sitcov.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Map;
import org.junit.jupiter.api.Test;

class TracedDrawsTest {
    private static double[] uniform(int bins) {
        double[] p = new double[bins];
        java.util.Arrays.fill(p, 1.0);
        return p;
    }

    private static double[] allIn(int bins, int bin) {
        double[] p = new double[bins];
        p[bin] = 1.0;
        return p;
    }

    @Test
    void theGeneratorUnderNoTiltDrawsTheMapItAlwaysDrew() {
        for (long seed = 1; seed <= 100; seed++) {
            assertEquals(MapGenerator.generate(seed), MapGenerator.generate(seed, Tilt.NOMINAL).map(), "seed " + seed);
        }
    }

    @Test
    void aNominalMapsTracedLikelihoodIsThatOfItsThreeCounts() {
        double expected = -(Math.log(20) + Math.log(5) + Math.log(15));
        for (long seed = 1; seed <= 50; seed++) {
            TracedMap traced = MapGenerator.generate(seed, Tilt.NOMINAL);
            assertEquals(expected, traced.trace().logNominal(), 1e-12, "seed " + seed);
            assertEquals(traced.trace().logNominal(), traced.trace().logProposal(), "seed " + seed);
            assertEquals(1.0, traced.trace().weight(), "seed " + seed);
        }
    }

    @Test
    void theTracedBinsOfTheCountsAreTheCountsTheMapRequested() {
        for (long seed = 1; seed <= 50; seed++) {
            TracedMap traced = MapGenerator.generate(seed, Tilt.NOMINAL);
            Layout l = traced.map().layout();
            assertEquals(1, traced.trace().draws(DrawSite.JUNCTION_ATTEMPTS, l.junctionAttempts() - 5));
            assertEquals(1, traced.trace().draws(DrawSite.PARKED_CARS, l.parkedCarsRequested() - 5));
            assertEquals(1, traced.trace().draws(DrawSite.MOVING_CARS, traced.map().movingCarsRequested() - 5));
        }
    }

    @Test
    void aTiltEqualToTheGeneratorWeighsEveryMapOne() {
        Map<DrawSite, double[]> p = new java.util.EnumMap<>(DrawSite.class);
        for (DrawSite s : DrawSite.values()) {
            p.put(s, uniform(s.bins()));
        }
        Tilt same = Tilt.of(p);
        for (long seed = 1; seed <= 50; seed++) {
            assertEquals(1.0, MapGenerator.generate(seed, same).trace().weight(), 1e-12, "seed " + seed);
        }
    }

    @Test
    void aTiltOnOneCountDrawsOnlyItsBinAndWeighsTheMapByTheBinsLostOdds() {
        Tilt crowded = Tilt.of(Map.of(DrawSite.MOVING_CARS, allIn(15, 14)));
        for (long seed = 1; seed <= 30; seed++) {
            TracedMap traced = MapGenerator.generate(seed, crowded);
            assertEquals(19, traced.map().movingCarsRequested(), "seed " + seed);
            // p_nominal / p_proposal of the one tilted draw: (1/15) / 1
            assertEquals(1.0 / 15, traced.trace().weight(), 1e-12, "seed " + seed);
        }
    }

    @Test
    void aTiltOnACoordinateKeepsEachTryInItsBinAndWeighsEveryTry() {
        Tilt west = Tilt.of(Map.of(DrawSite.TARGET_X, allIn(5, 0)));
        for (long seed = 1; seed <= 30; seed++) {
            TracedMap traced = MapGenerator.generate(seed, west);
            traced.map().layout().target().ifPresent(t -> assertTrue(t.position().x() <= 40, t.toString()));
            int tries = traced.trace().draws(DrawSite.TARGET_X, 0);
            // each try: density 1 under the generator, 5 x 1 under the tilt
            assertEquals(Math.pow(5, -tries), traced.trace().weight(), 1e-12, "seed " + seed);
        }
    }

    @Test
    void weightedMapsUnderATiltGiveTheGeneratorsMeanCount() {
        Tilt tilt = Tilt.of(Map.of(DrawSite.MOVING_CARS, new double[] {8, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 4}));
        int n = 3000;
        double sum = 0;
        double sum2 = 0;
        for (long seed = 1; seed <= n; seed++) {
            TracedMap traced = MapGenerator.generate(seed, tilt);
            double x = traced.trace().weight() * traced.map().movingCarsRequested();
            sum += x;
            sum2 += x * x;
        }
        double mean = sum / n;
        double se = Math.sqrt((sum2 / n - mean * mean) / n);
        // the generator draws 5..19 moving cars with equal odds: a mean of 12
        assertTrue(Math.abs(mean - 12) < 3 * se, "weighted mean " + mean + " +- " + se);
    }

    @Test
    void aTiltRefusesAListOfTheWrongLengthOrWithoutMass() {
        assertThrows(IllegalArgumentException.class, () -> Tilt.of(Map.of(DrawSite.PARKED_CARS, new double[4])));
        assertThrows(IllegalArgumentException.class, () -> Tilt.of(Map.of(DrawSite.PARKED_CARS, new double[5])));
        assertThrows(IllegalArgumentException.class, () -> Tilt.of(Map.of(DrawSite.PARKED_CARS,
                new double[] {1, 1, -1, 1, 1})));
    }
}
