package sitcov.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import sitcov.geom.Compass;
import sitcov.geom.Rect;
import sitcov.geom.Vec2;

class RoadTest {
    private final Road eastWest = new Road(0, Axis.EAST_WEST, 50, 20, 180);
    private final Road northSouth = new Road(1, Axis.NORTH_SOUTH, 100, 10, 90);

    @Test
    void theSurfaceIsSixMetresWideAndEndsAtTheRoadEnds() {
        assertEquals(new Rect(20, 47, 180, 53), eastWest.surface());
        assertEquals(new Rect(97, 10, 103, 90), northSouth.surface());
        assertTrue(eastWest.contains(20, 53));
        assertFalse(eastWest.contains(19.9, 50));
    }

    @Test
    void trafficKeepsLeftSoEastboundIsTheNorthHalfAndNorthboundTheWestHalf() {
        assertEquals(Compass.EAST, eastWest.laneDirectionAt(100, 49));
        assertEquals(Compass.WEST, eastWest.laneDirectionAt(100, 51));
        assertEquals(Compass.NORTH, northSouth.laneDirectionAt(99, 50));
        assertEquals(Compass.SOUTH, northSouth.laneDirectionAt(101, 50));
        assertEquals(48.5, eastWest.laneCentre(Compass.EAST));
        assertEquals(101.5, northSouth.laneCentre(Compass.SOUTH));
    }

    @Test
    void aRoadHasNoLaneAcrossItsAxis() {
        assertThrows(IllegalArgumentException.class, () -> eastWest.laneCentre(Compass.NORTH));
    }

    @Test
    void aRoadBetweenTwoPointsMustBeAxisAligned() {
        assertEquals(northSouth, Road.between(1, new Vec2(100, 90), new Vec2(100, 10)));
        assertThrows(IllegalArgumentException.class, () -> Road.between(2, new Vec2(0, 0), new Vec2(5, 5)));
    }
}
