package sitcov.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.IntSummaryStatistics;
import java.util.List;
import java.util.function.ToIntFunction;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

class MapGeneratorTest {
    private static final int SEEDS = 10_000;
    private static final List<WorldMap> MAPS = new ArrayList<>();

    @BeforeAll
    static void generateTenThousandMaps() {
        for (long seed = 1; seed <= SEEDS; seed++) {
            MAPS.add(MapGenerator.generate(seed));
        }
    }

    @Test
    void theSameSeedGivesAnEqualMap() {
        for (long seed : new long[] {1, 42, -7, Long.MAX_VALUE}) {
            assertEquals(MapGenerator.generate(seed), MapGenerator.generate(seed), "seed " + seed);
        }
    }

    @Test
    void differentSeedsGiveDifferentMaps() {
        long distinctLayouts = MAPS.stream().map(m -> m.layout().roads()).distinct().count();
        assertEquals(SEEDS, distinctLayouts, "every one of " + SEEDS + " seeds should give its own road tree");
    }

    @Test
    void theLayoutAloneIsTheLayoutOfTheWholeMap() {
        for (long seed = 1; seed <= 200; seed++) {
            assertEquals(MAPS.get((int) seed - 1).layout(), MapGenerator.layout(seed), "seed " + seed);
        }
    }

    @Test
    void noMapOfTenThousandBreaksARule() {
        List<String> broken = new ArrayList<>();
        for (WorldMap map : MAPS) {
            Invariants.violations(map).forEach(v -> broken.add("seed " + map.seed() + ": " + v));
        }
        assertEquals(List.of(), broken.subList(0, Math.min(20, broken.size())), broken.size() + " violations");
    }

    @Test
    void everyMapCanBeRun() {
        assertTrue(MAPS.stream().allMatch(m -> m.layout().isRunnable()));
    }

    @Test
    void countsStayInsideTheirRangesAndOmissionsAccountForEveryShortfall() {
        for (WorldMap map : MAPS) {
            Layout l = map.layout();
            String seed = "seed " + map.seed();
            assertTrue(l.junctionAttempts() >= 5 && l.junctionAttempts() <= 24, seed);
            assertTrue(l.tJunctionCount() <= l.junctionAttempts(), seed);
            assertEquals(l.roads().size(), l.tJunctionCount() + 1, seed + ": one road per T-junction, plus the first");
            assertTrue(l.parkedCarsRequested() >= 5 && l.parkedCarsRequested() <= 9, seed);
            assertTrue(map.movingCarsRequested() >= 5 && map.movingCarsRequested() <= 19, seed);
            long omittedParked = l.omissions().stream().filter(o -> o.element().startsWith("parked car")).count();
            assertEquals(l.parkedCarsRequested(), l.parkedCars().size() + omittedParked, seed);
            long omittedJunctions = l.omissions().stream().filter(o -> o.element().startsWith("T-junction")).count();
            assertEquals(l.junctionAttempts(), l.tJunctionCount() + omittedJunctions, seed);
            assertEquals(map.movingCarsRequested(), map.movingCars().size() + map.movingCarOmissions().size(), seed);
        }
    }

    /**
     * Means near those the original implementation measured (its seeds 1..20 000). Tolerance ±10 %: our rules differ
     * from the original's by a 1 m clearance between roads that are not parent and branch (fewer
     * branches fit), by keeping parked cars' whole bodies out of junction squares, and by its
     * off-by-one (a place found on the last try counts); we measure 9.8 T-junctions, 21.6
     * junctions, 10.8 roads, 4.1 parked cars and 11.6 moving cars over seeds 1..10 000.
     */
    @Test
    void meanCountsAreInTheNeighbourhoodOfTheOriginals() {
        assertNear(10.4, stats(m -> (int) m.layout().tJunctionCount()).getAverage(), 0.10, "T-junctions");
        assertNear(22.8, stats(m -> m.layout().junctions().size()).getAverage(), 0.10, "junctions");
        assertNear(11.4, stats(m -> m.layout().roads().size()).getAverage(), 0.10, "roads");
        assertNear(11.9, stats(m -> m.movingCars().size()).getAverage(), 0.10, "moving cars");
        assertNear(4.3, stats(m -> m.layout().parkedCars().size()).getAverage(), 0.10, "parked cars");
    }

    @Test
    void observedRangesSpanMostOfWhatTheRulesAllow() {
        IntSummaryStatistics parked = stats(m -> m.layout().parkedCars().size());
        IntSummaryStatistics moving = stats(m -> m.movingCars().size());
        assertEquals(0, parked.getMin());
        assertEquals(9, parked.getMax());
        assertTrue(moving.getMax() == 19 && moving.getMin() <= 5, moving.toString());
    }

    @Test
    void movingCarsDoNotChangeTheLayout() {
        WorldMap map = MAPS.get(0);
        assertEquals(map.layout(), MapGenerator.withMovingCars(map.layout()).layout());
        assertEquals(map, MapGenerator.withMovingCars(MapGenerator.layout(1)));
        assertNotEquals(map.movingCars(), MAPS.get(1).movingCars());
    }

    private static IntSummaryStatistics stats(ToIntFunction<WorldMap> count) {
        return MAPS.stream().mapToInt(count).summaryStatistics();
    }

    private static void assertNear(double expected, double actual, double relative, String what) {
        assertTrue(Math.abs(actual - expected) <= relative * expected,
                what + ": mean " + actual + " is not within " + (relative * 100) + "% of " + expected);
    }
}
