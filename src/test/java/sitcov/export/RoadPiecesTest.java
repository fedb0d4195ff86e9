package sitcov.export;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import sitcov.geom.Vec2;
import sitcov.world.Axis;
import sitcov.world.Junction;
import sitcov.world.Layout;
import sitcov.world.Road;

class RoadPiecesTest {
    private static Layout layout(List<Road> roads, List<Junction> junctions) {
        return new Layout(0, roads, junctions, List.of(), Optional.empty(), Optional.empty(), 0, 0, List.of());
    }

    @Test
    void aRoadIsCutAtEachTJunctionSquareIntoPiecesThatNameTheArmsTheyAre() {
        Road main = new Road(0, Axis.EAST_WEST, 50, 0, 100);
        Road branch = new Road(1, Axis.NORTH_SOUTH, 40, 20, 50);
        Junction t = new Junction(0, new Vec2(40, 50), 23, 23, 0, 23);
        RoadPieces pieces = RoadPieces.of(layout(List.of(main, branch), List.of(t)));
        // main: 0..37 and 43..100; branch: 20..47 (its end inside the square is cut off)
        assertEquals(3, pieces.pieces().size());
        assertEquals(37, pieces.arm(t, sitcov.geom.Compass.WEST).length(), 1e-12);
        assertEquals(57, pieces.arm(t, sitcov.geom.Compass.EAST).length(), 1e-12);
        assertEquals(27, pieces.arm(t, sitcov.geom.Compass.NORTH).length(), 1e-12);
        // an east-west piece starts at its west end: the east arm meets the junction at its start
        assertEquals("start", pieces.arm(t, sitcov.geom.Compass.EAST).contactPointAt(t));
        assertEquals("end", pieces.arm(t, sitcov.geom.Compass.WEST).contactPointAt(t));
        // a north-south piece points north, so the piece north of the junction starts there too
        assertEquals("start", pieces.arm(t, sitcov.geom.Compass.NORTH).contactPointAt(t));
    }

    @Test
    void twoJunctionSquaresThatTouchAreRefusedWithTheReasonForNoRoadLiesBetweenThem() {
        Road main = new Road(0, Axis.EAST_WEST, 50, 0, 100);
        Road a = new Road(1, Axis.NORTH_SOUTH, 40, 20, 50);
        Road b = new Road(2, Axis.NORTH_SOUTH, 46, 20, 50);
        Junction j1 = new Junction(0, new Vec2(40, 50), 23, 23, 0, 23);
        Junction j2 = new Junction(1, new Vec2(46, 50), 23, 23, 0, 23);
        IllegalStateException e = assertThrows(IllegalStateException.class,
                () -> RoadPieces.of(layout(List.of(main, a, b), List.of(j1, j2))).arm(j1, sitcov.geom.Compass.EAST));
        assertTrue(e.getMessage().contains("OpenDRIVE joins junctions only by roads"), e.getMessage());
    }
}
