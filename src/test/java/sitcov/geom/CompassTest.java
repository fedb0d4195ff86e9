package sitcov.geom;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;

class CompassTest {

    @Test
    void northIsMinusYAndLeftOfEastIsNorth() {
        assertEquals(-1, Compass.NORTH.dy());
        assertEquals(Compass.NORTH, Compass.EAST.left());
        assertEquals(Compass.SOUTH, Compass.EAST.right());
        assertEquals(Compass.WEST, Compass.EAST.opposite());
        assertEquals(Compass.EAST, Compass.NORTH.right());
    }

    @Test
    void aBearingQuantisesToTheNearestAxisWithTheOriginalsTieBreaks() {
        assertEquals(Compass.SOUTH, Compass.nearest(44.9));
        assertEquals(Compass.EAST, Compass.nearest(45));
        assertEquals(Compass.NORTH, Compass.nearest(135));
        assertEquals(Compass.WEST, Compass.nearest(225));
        assertEquals(Compass.SOUTH, Compass.nearest(315));
        assertEquals(Compass.SOUTH, Compass.nearest(-10));
    }

    @Test
    void onlyExactAxisBearingsNameADirection() {
        assertEquals(Compass.WEST, Compass.ofBearing(270));
        assertEquals(Compass.SOUTH, Compass.ofBearing(360));
        assertThrows(IllegalArgumentException.class, () -> Compass.ofBearing(100));
    }
}
