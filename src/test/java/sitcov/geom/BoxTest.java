package sitcov.geom;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;

class BoxTest {
    private static final double EPS = 1e-9;

    @Test
    void aCarHeadingEastTrailsBehindItsFrontCentre() {
        Box car = Box.behind(10, 20, 90, 5, 2);

        assertEquals(new Rect(5, 19, 10, 21), roundedBounds(car));
        assertTrue(car.contains(9.9, 20));
        assertTrue(car.contains(5, 21));
        assertFalse(car.contains(10.1, 20));
        assertFalse(car.contains(7, 21.2));
    }

    @Test
    void aParkedCarOnANorthSouthRoadIsLongInY() {
        Box parked = Box.centred(0, 0, 0, 5, 2);

        Rect b = roundedBounds(parked);
        assertEquals(2, b.width(), EPS);
        assertEquals(5, b.height(), EPS);
    }

    @Test
    void cornersGoRoundTheBox() {
        double[] c = Box.centred(0, 0, 90, 4, 2).corners();

        // heading east: front is +x; the side axis is (cos, -sin) = (0, -1)
        assertArrayEquals(new double[] {2, -1, 2, 1, -2, 1, -2, -1}, c, EPS);
    }

    @Test
    void boxesThatOnlyTouchDoNotOverlap() {
        Box a = Box.centred(0, 0, 90, 4, 2);
        Box touching = Box.centred(4, 0, 90, 4, 2);
        Box overlapping = Box.centred(3.9, 0, 90, 4, 2);

        assertFalse(a.overlaps(touching));
        assertTrue(a.overlaps(overlapping));
        assertTrue(overlapping.overlaps(a));
    }

    @Test
    void aRotatedBoxIsSeparatedOnlyAlongItsOwnAxis() {
        // Bounding boxes overlap but the diamond's corner does not reach the square.
        Box square = Box.centred(0, 0, 0, 2, 2);
        Box diamond = Box.centred(2.3, 2.3, 45, 2, 2);

        assertTrue(square.bounds().overlaps(diamond.bounds()));
        assertFalse(square.overlaps(diamond));
        assertFalse(diamond.overlaps(square.bounds()));
    }

    @Test
    void aBoxOverlapsARectangleOnlyWhenInteriorsMeet() {
        Box car = Box.behind(10, 0, 90, 5, 2);

        assertTrue(car.overlaps(new Rect(9, -5, 12, 5)));
        assertFalse(car.overlaps(new Rect(10, -5, 12, 5)));
        assertFalse(Box.centred(0, 0, 45, 2, 2).overlaps(new Rect(0.8, 0.8, 3, 3)));
    }

    @Test
    void aBoxIsCoveredByTheUnionOfRectanglesOnlyWhenNoPartSticksOut() {
        // A T: an east-west road and a road going south from x = 20.
        List<Rect> tee = List.of(new Rect(0, -3, 40, 3), new Rect(17, 0, 23, 30));

        assertTrue(Box.behind(10, 1.5, 90, 5, 2).isCoveredBy(tee));
        assertTrue(Box.behind(20, 10, 0, 5, 2).isCoveredBy(tee), "down the branch");
        assertTrue(Box.behind(20, 5, 0, 5, 2).isCoveredBy(tee), "straddling both roads");
        assertFalse(Box.behind(10, 2.5, 90, 5, 2).isCoveredBy(tee), "over the kerb");
        assertFalse(Box.centred(16.5, 4, 45, 5, 2).isCoveredBy(tee), "cutting the corner");
    }

    private static Rect roundedBounds(Box box) {
        Rect b = box.bounds();
        return new Rect(round(b.minX()), round(b.minY()), round(b.maxX()), round(b.maxY()));
    }

    private static double round(double v) {
        return Math.round(v * 1e6) / 1e6;
    }
}
