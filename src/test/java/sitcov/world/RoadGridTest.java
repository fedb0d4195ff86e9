package sitcov.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import sitcov.geom.Rect;

class RoadGridTest {

    @Test
    void everyRoadThatHoldsAPointIsAmongTheRoadsNearItInRoadOrder() {
        SplittableRandom random = new SplittableRandom(3);
        int held = 0;
        for (long seed = 1; seed <= 30; seed++) {
            RoadNetwork network = RoadNetwork.of(MapGenerator.layout(seed));
            List<Road> roads = network.roads();
            for (Road road : roads) {
                Rect s = road.surface();
                // points on and a hair either side of each edge and corner, and inside
                double[] xs = {s.minX(), Math.nextDown(s.minX()), s.minX() - 1e-9, s.maxX(), Math.nextUp(s.maxX()),
                        s.maxX() + 1e-9, s.maxX() + 2e-9, (s.minX() + s.maxX()) / 2, random.nextDouble(s.minX(), s.maxX())};
                double[] ys = {s.minY(), Math.nextDown(s.minY()), s.minY() - 1e-9, s.maxY(), Math.nextUp(s.maxY()),
                        s.maxY() + 1e-9, s.maxY() + 2e-9, (s.minY() + s.maxY()) / 2, random.nextDouble(s.minY(), s.maxY())};
                for (double x : xs) {
                    for (double y : ys) {
                        held += check(network, roads, x, y);
                    }
                }
            }
            for (int k = 0; k < 500; k++) {
                check(network, roads, random.nextDouble(-50, 400), random.nextDouble(-50, 400));
            }
        }
        assertTrue(held > 1000, "the points tried lie on roads: " + held);
    }

    @Test
    void aPointOffTheMapOrNaNHasNoRoadsNear() {
        RoadNetwork network = RoadNetwork.of(MapGenerator.layout(1));
        assertEquals(0, network.roadsNear(Double.NaN, 0).length);
        assertEquals(0, network.roadsNear(-1e6, -1e6).length);
    }

    /** The roads holding the point, by a scan of all, against those found among the roads near it; 1 when some road holds it. */
    private static int check(RoadNetwork network, List<Road> roads, double x, double y) {
        List<Integer> all = new ArrayList<>();
        for (int index = 0; index < roads.size(); index++) {
            if (roads.get(index).contains(x, y)) {
                all.add(index);
            }
        }
        List<Integer> near = new ArrayList<>();
        int previous = -1;
        for (int index : network.roadsNear(x, y)) {
            assertTrue(index > previous, "road order");
            previous = index;
            if (roads.get(index).contains(x, y)) {
                near.add(index);
            }
        }
        assertEquals(all, near, "at (" + x + ", " + y + ")");
        return all.isEmpty() ? 0 : 1;
    }
}
