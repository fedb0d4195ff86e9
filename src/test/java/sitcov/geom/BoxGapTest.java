package sitcov.geom;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

class BoxGapTest {
    private static final double EPS = 1e-9;
    private static final double ROOT2 = Math.sqrt(2);

    /** A 2 m square centred on the origin: x and y both in [-1, 1]. */
    private static final Box UNIT = Box.centred(0, 0, 0, 2, 2);

    @Test
    void parallelCarsOneMetreApartAreOneMetreApart() {
        Box left = Box.centred(0, 0, 0, 5, 2);   // x in [-1, 1], long in y
        Box right = Box.centred(3, 1, 0, 5, 2);  // x in [2, 4]

        assertEquals(1, BoxGap.signedDistance(left, right), EPS);
        assertEquals(1, BoxGap.distance(right, left), EPS);
    }

    @Test
    void diagonalNeighboursAreAsFarApartAsTheirNearestCorners() {
        Box far = Box.centred(4, 5, 0, 2, 2); // [3, 5] x [4, 6]: nearest corners (1, 1) and (3, 4)

        assertEquals(Math.sqrt(4 + 9), BoxGap.signedDistance(UNIT, far), EPS);
    }

    @Test
    void aBoxTurnedFortyFiveDegreesPointsItsCornerAtTheOther() {
        Box diamond = Box.centred(3, 0, 45, 2, 2); // its nearest corner at x = 3 - sqrt 2, on the x axis

        assertEquals(2 - ROOT2, BoxGap.signedDistance(UNIT, diamond), EPS);
        assertEquals(2 - ROOT2, BoxGap.signedDistance(diamond, UNIT), EPS);
    }

    @Test
    void boxesOverlappingByThirtyCentimetresAreThatDeepInEachOther() {
        Box overlapping = Box.centred(1.7, 0.5, 0, 2, 2); // x in [0.7, 2.7]: 0.3 into the square; y 1.5 in

        assertEquals(-0.3, BoxGap.signedDistance(UNIT, overlapping), EPS);
        assertEquals(0, BoxGap.distance(UNIT, overlapping));
    }

    @Test
    void aCornerPokedInIsAsDeepAsTheCornerGoes() {
        // the diamond's corner reaches 0.2 m into the square; along the diamond's own axes they overlap more
        Box diamond = Box.centred(1 + ROOT2 - 0.2, 0, 45, 2, 2);

        assertEquals(-0.2, BoxGap.signedDistance(UNIT, diamond), EPS);
    }

    @Test
    void touchingBoxesAreNoDistanceApartAndDoNotOverlap() {
        Box beside = Box.centred(2, 0.5, 0, 2, 2);

        assertEquals(0, BoxGap.signedDistance(UNIT, beside), EPS);
        assertFalse(UNIT.overlaps(beside));
    }

    @Test
    void theSignedDistanceIsNegativeExactlyWhenTheBoxesOverlap() {
        SplittableRandom random = new SplittableRandom(30);
        int overlapping = 0;
        for (int i = 0; i < 2000; i++) {
            Box a = Box.centred(random.nextDouble(-3, 3), random.nextDouble(-3, 3), random.nextDouble(360), 5, 2);
            Box b = Box.centred(random.nextDouble(-3, 3), random.nextDouble(-3, 3), random.nextDouble(360), 2, 2);
            double signed = BoxGap.signedDistance(a, b);
            assertEquals(a.overlaps(b), signed < 0, a + " " + b + " " + signed);
            if (signed < 0) {
                overlapping++;
            }
        }
        assertTrue(overlapping > 100 && overlapping < 1900, "both kinds were drawn: " + overlapping);
    }

    @Test
    void theDistanceOfBoxesApartIsTheLeastBetweenPointsOfTheirEdges() {
        SplittableRandom random = new SplittableRandom(31);
        int apart = 0;
        for (int i = 0; i < 200; i++) {
            Box a = Box.centred(0, 0, random.nextDouble(360), 5, 2);
            Box b = Box.centred(random.nextDouble(-8, 8), random.nextDouble(-8, 8), random.nextDouble(360), 5, 2);
            double gap = BoxGap.signedDistance(a, b);
            if (gap <= 0) {
                continue;
            }
            apart++;
            double sampled = sampledDistance(a.corners(), b.corners(), 200);
            assertTrue(gap <= sampled + EPS, "no pair of edge points is nearer than the distance");
            assertEquals(sampled, gap, 0.03, "and the sampled pairs come within the sampling step of it");
        }
        assertTrue(apart > 100);
    }

    @Test
    void carsDrivingHeadOnMeetWhenTheGapIsClosed() {
        // a heads east at 1 m a tick, b west at 1 m a tick, 10 m between their fronts
        double t = BoxGap.timeToContact(0, 0, 1, 0, 2.5, 1, 1, 0, 15, 0, -1, 0, 2.5, 1, -1, 0);

        assertEquals(5, t, EPS);
    }

    @Test
    void carsInTheirOwnLanesPassingEachOtherNeverMeet() {
        // 3 m between the lanes' centres, 2 m wide cars: 1 m apart sideways all along
        double t = BoxGap.timeToContact(0, 0, 1, 0, 2.5, 1, 1, 0, 15, 3, -1, 0, 2.5, 1, -1, 0);

        assertEquals(Double.POSITIVE_INFINITY, t);
    }

    @Test
    void aCarDrawingAwayNeverMeetsAndOneAlreadyTouchingMeetsNow() {
        assertEquals(Double.POSITIVE_INFINITY, BoxGap.timeToContact(0, 0, 1, 0, 2.5, 1, 0, 0, 10, 0, 1, 0, 2.5, 1, 1, 0));
        assertEquals(0, BoxGap.timeToContact(0, 0, 1, 0, 2.5, 1, 0, 0, 4, 0, 1, 0, 2.5, 1, 1, 0));
    }

    @Test
    void aCrossingCarMeetsWhenItsFrontReachesTheOthersSide() {
        // a stands still across x in [-1, 1]; b comes down from y = 10 at 2 m a tick, its front (y - 2.5) 8 m off
        double t = BoxGap.timeToContact(0, 0, 0, 1, 1, 1, 0, 0, 0.5, 10, 0, 1, 2.5, 1, 0, -2);

        assertEquals((10 - 2.5 - 1) / 2.0, t, EPS);
    }

    @Test
    void aSegmentBesideABoxIsItsDistanceAwayAndOneThroughItIsAsDeepAsItReaches() {
        assertEquals(2, BoxGap.segmentSignedDistance(3, -5, 3, 5, 0, 0, 1, 0, 1, 1), EPS);
        assertEquals(-0.5, BoxGap.segmentSignedDistance(0.5, -5, 0.5, 5, 0, 0, 1, 0, 1, 1), EPS);
        // ending inside: its end is 0.4 m from the nearest edge
        assertEquals(-0.4, BoxGap.segmentSignedDistance(0.2, 5, 0.2, 0.6, 0, 0, 1, 0, 1, 1), EPS);
        // past a corner: the corner (1, 1) is nearest, sqrt 2 from (2, 2)
        assertEquals(ROOT2, BoxGap.segmentSignedDistance(2, 2, 2, 8, 0, 0, 1, 0, 1, 1), EPS);
        assertEquals(0, BoxGap.segmentSignedDistance(1, -5, 1, 5, 0, 0, 1, 0, 1, 1), EPS);
    }

    /** The least distance between points spaced evenly along the edges of two polygons. */
    private static double sampledDistance(double[] a, double[] b, int perEdge) {
        double best = Double.POSITIVE_INFINITY;
        for (int i = 0; i < 4; i++) {
            for (int s = 0; s <= perEdge; s++) {
                double ax = lerp(a, i, 0, s / (double) perEdge);
                double ay = lerp(a, i, 1, s / (double) perEdge);
                for (int j = 0; j < 4; j++) {
                    for (int r = 0; r <= perEdge; r++) {
                        double bx = lerp(b, j, 0, r / (double) perEdge);
                        double by = lerp(b, j, 1, r / (double) perEdge);
                        best = Math.min(best, Math.hypot(ax - bx, ay - by));
                    }
                }
            }
        }
        return best;
    }

    private static double lerp(double[] corners, int edge, int coordinate, double t) {
        int next = (edge + 1) % 4;
        return corners[2 * edge + coordinate] * (1 - t) + corners[2 * next + coordinate] * t;
    }
}
