package sitcov.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import sitcov.geom.Vec2;

/**
 * A situation file whose ids or junction arms contradict its geometry is refused
 * (src/main/java/sitcov/cli/README.md, "Maps and situation files"): generated maps are written, then one id or one
 * arm length is changed in the text.
 */
class SituationIdMutationTest {
    /** Maps with T-junctions, several parked cars and a Target each (checked in the first test). */
    private static final long[] SEEDS = {1, 2, 5, 13, 42};

    private static List<String> linesOf(long seed) {
        return new ArrayList<>(SituationFile.format(MapGenerator.generate(seed)).lines().toList());
    }

    /** The indices of the lines of one kind, in file order (the n-th is element n: ids are indices). */
    private static List<Integer> linesOf(List<String> lines, String keyword) {
        List<Integer> at = new ArrayList<>();
        for (int i = 0; i < lines.size(); i++) {
            if (lines.get(i).startsWith(keyword + " ")) {
                at.add(i);
            }
        }
        return at;
    }

    private static List<String> with(List<String> lines, int at, String line) {
        List<String> mutant = new ArrayList<>(lines);
        mutant.set(at, line);
        return mutant;
    }

    private static SituationFormatException refused(List<String> lines, String what) {
        return assertThrows(SituationFormatException.class, () -> SituationFile.parse(lines, "mutant.situation"), what);
    }

    @Test
    void theUnmutatedFilesLoadAsTheGeneratedMapsAndWriteBackTheSameText() throws Exception {
        for (long seed : SEEDS) {
            WorldMap map = MapGenerator.generate(seed);
            String text = SituationFile.format(map);
            WorldMap read = SituationFile.parse(text.lines().toList(), "seed " + seed);
            assertEquals(map, read);
            assertEquals(text, SituationFile.format(read));
            assertTrue(map.layout().isRunnable() && map.layout().parkedCars().size() >= 2
                    && map.layout().tJunctionCount() >= 1, "seed " + seed + " has what the mutants change");
        }
    }

    @Test
    void aTargetNamingAnyRoadButTheOneItStandsOnIsRefusedNamingBoth() {
        int mutants = 0;
        for (long seed : SEEDS) {
            List<String> lines = linesOf(seed);
            Layout layout = MapGenerator.layout(seed);
            Target target = layout.target().orElseThrow();
            int at = linesOf(lines, "target").get(0);
            for (Road other : layout.roads()) {
                if (other.id() == target.roadId()) {
                    continue;
                }
                String[] w = lines.get(at).split(" ");
                SituationFormatException e = refused(with(lines, at, w[0] + " " + w[1] + " " + w[2] + " " + other.id()),
                        "seed " + seed + ", Target naming road " + other.id());
                assertEquals(at + 1, e.line(), e.getMessage());
                assertTrue(e.getMessage().startsWith("mutant.situation:" + (at + 1) + ": breaks a rule of the world: the Target at ")
                        && e.getMessage().contains("names road " + other.id() + " but stands on road " + target.roadId()
                        + ": set its ROAD_ID to " + target.roadId()), e.getMessage());
                mutants++;
            }
        }
        assertTrue(mutants >= 20, mutants + " mutants");
    }

    @Test
    void aParkedCarNamingAnotherRoadOrLyingAcrossItsRoadIsRefusedAtItsLine() {
        int mutants = 0;
        for (long seed : SEEDS) {
            List<String> lines = linesOf(seed);
            Layout layout = MapGenerator.layout(seed);
            List<Integer> carLines = linesOf(lines, "parked-car");
            assertEquals(layout.parkedCars().size(), carLines.size());
            for (ParkedCar car : layout.parkedCars()) {
                int at = carLines.get(car.id());
                String[] w = lines.get(at).split(" ");
                int roads = layout.roads().size();
                for (int step = 1; step <= Math.min(4, roads - 1); step++) {
                    // four other roads a car, the ones after its own in id order (0 follows the last)
                    Road other = layout.roads().get((car.roadId() + step) % roads);
                    String line = String.join(" ", w[0], w[1], String.valueOf(other.id()), w[3], w[4], w[5]);
                    SituationFormatException e = refused(with(lines, at, line), "seed " + seed + ": " + line);
                    assertEquals(at + 1, e.line(), e.getMessage());
                    assertTrue(e.getMessage().contains("parked car " + car.id() + " at ")
                            && e.getMessage().contains("names road " + other.id() + " but stands on road " + car.roadId()),
                            e.getMessage());
                    mutants++;
                }
                Axis across = car.axis().other();
                String line = String.join(" ", w[0], w[1], w[2], w[3], w[4], across.name());
                SituationFormatException e = refused(with(lines, at, line), "seed " + seed + ": " + line);
                assertEquals(at + 1, e.line(), e.getMessage());
                mutants++;
            }
        }
        assertTrue(mutants >= 60, mutants + " mutants");
    }

    @Test
    void aJunctionArmLongerOrShorterThanItsRoadsReachIsRefusedWithTheRightLengths() {
        int mutants = 0;
        for (long seed : SEEDS) {
            List<String> lines = linesOf(seed);
            Layout layout = MapGenerator.layout(seed);
            List<Integer> junctionLines = linesOf(lines, "junction");
            for (Junction j : layout.junctions()) {
                int at = junctionLines.get(j.id());
                String[] w = lines.get(at).split(" ");
                for (int k = 4; k < 8; k++) {
                    double arm = Double.parseDouble(w[k]);
                    if (arm == 0 && j.id() > 0) {
                        continue; // an arm where no road runs breaks the count of arms, checked once a map
                    }
                    // a shorter arm (half, or a millimetre less) or a longer one, taken in turn
                    double[] wrongs = {arm / 2, arm - 0.001, arm + 1};
                    for (double length : arm == 0 ? new double[] {5} : new double[] {wrongs[(j.id() + k) % 3]}) {
                        String[] m = w.clone();
                        m[k] = String.valueOf(length);
                        SituationFormatException e = refused(with(lines, at, String.join(" ", m)),
                                "seed " + seed + ": " + String.join(" ", m));
                        assertEquals(at + 1, e.line(), e.getMessage());
                        assertTrue(e.getMessage().contains("junction " + j.id() + " has "), e.getMessage());
                        if (arm > 0) {
                            // the message gives back the lengths the file had
                            assertTrue(e.getMessage().contains("set ARM_NORTH ARM_EAST ARM_SOUTH ARM_WEST to "
                                    + j.armNorth() + " " + j.armEast() + " " + j.armSouth() + " " + j.armWest()), e.getMessage());
                        }
                        mutants++;
                    }
                }
            }
        }
        assertTrue(mutants >= 150, mutants + " mutants");
    }

    @Test
    void aParkedCarThatNamedAnotherRoadCanNoLongerEscapeTheSpacingRule() {
        // cars staggered 6 m apart across the straight road break the spacing rule; before the id check,
        // naming a road the second car does not stand on hid it from the rule, and the pair blocked the road
        List<Road> roads = List.of(Situations.straightRoad(), new Road(1, Axis.NORTH_SOUTH, 100, 50, 95));
        List<Junction> junctions = new ArrayList<>();
        for (Vec2 centre : List.of(new Vec2(23, 50), new Vec2(177, 50), new Vec2(100, 50), new Vec2(100, 92))) {
            junctions.add(RoadTreeBuilder.withArms(junctions.size(), centre, roads));
        }
        ParkedCar north = Situations.parkedInEastboundLane(0, 60);
        Vec2 southKerb = new Vec2(66, 50 + 1.675);
        Layout honest = Situations.layout(roads, junctions,
                List.of(north, new ParkedCar(1, 0, southKerb, Axis.EAST_WEST)), null, null);
        Layout hiding = Situations.layout(roads, junctions,
                List.of(north, new ParkedCar(1, 1, southKerb, Axis.EAST_WEST)), null, null);
        assertEquals(List.of("parked cars 0 and 1 stand nearer along their road than the generator spaces them"),
                Invariants.violations(honest));
        assertEquals(List.of("parked car 1 at (66.0, 51.675) names road 1 but stands on road 0: set its ROAD_ID to 0"),
                Invariants.violations(hiding));
    }
}
