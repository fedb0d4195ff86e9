package sitcov.oracle;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import sitcov.geom.Bearing;
import sitcov.geom.Box;
import sitcov.world.RoadNetwork;
import sitcov.world.Situations;

/**
 * The road's edge on the T of {@link Situations#tee()}: the main road's surface is x ∈ [10, 190],
 * y ∈ [27, 33]; the branch's x ∈ [97, 103], y ∈ [30, 90]. Boxes are 2 m × 2 m.
 */
class RoadEdgesTest {
    private static final double EPS = 1e-9;
    private final RoadNetwork network = RoadNetwork.of(Situations.tee());
    private final RoadEdges edges = new RoadEdges(network.surfaces());

    @Test
    void theTeesEdgeHasEightPieces() {
        // the main road's north side, its south side either side of the branch, its two ends,
        // the branch's two sides south of the main road and its south end
        assertEquals(8, edges.pieces());
    }

    @Test
    void aCarInTheMiddleOfItsLaneIsHalfAMetreFromTheKerb() {
        assertEquals(0.5, margin(60, 28.5, 90), EPS);
    }

    @Test
    void aCarOverTheKerbIsAsFarOffAsItsWorstCorner() {
        assertEquals(-0.3, margin(60, 27.7, 90), EPS);
    }

    @Test
    void aCarCuttingTheInsideCornerIsAsFarOffAsTheCornerReachesIntoIt() {
        // turned 45°, its four corners on the road, the kerb's corner (97, 33) 0.2 m across and 0.2 m
        // down from its centre: along its side axis 0.2·√2 from the centre, so 1 − 0.2·√2 from its edge
        Box cutting = Box.centred(97.2, 32.8, 45, 2, 2);

        assertEquals(-(1 - 0.2 * Math.sqrt(2)), margin(97.2, 32.8, 45), EPS);
        assertFalse(network.isOnRoad(cutting), "the oracle finds it off the road too");
    }

    @Test
    void theMarginIsNegativeExactlyWhenTheOracleFindsTheFootprintOffTheRoad() {
        SplittableRandom random = new SplittableRandom(30);
        int off = 0;
        for (int i = 0; i < 3000; i++) {
            double x = random.nextDouble(90, 110);
            double y = random.nextDouble(24, 40);
            double bearing = random.nextDouble(360);
            double m = margin(x, y, bearing);
            boolean onRoad = network.isOnRoad(Box.centred(x, y, bearing, 2, 2));
            if (Math.abs(m) > EPS) {
                assertEquals(onRoad, m > 0, "at " + x + ", " + y + ", " + bearing + ": " + m);
            }
            off += onRoad ? 0 : 1;
        }
        assertTrue(off > 300 && off < 2700, "both kinds were drawn: " + off);
    }

    private double margin(double x, double y, double bearing) {
        return edges.margin(x, y, Bearing.dx(bearing), Bearing.dy(bearing), 1, 1);
    }
}
