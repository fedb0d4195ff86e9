package sitcov.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import sitcov.geom.Compass;
import sitcov.geom.Rect;
import sitcov.geom.Vec2;

class JunctionTest {
    private final Junction tee = Situations.tee().junctions().get(0);
    private final Junction deadEnd = Situations.tee().junctions().get(3);

    @Test
    void aTeeHasThreeArmsAndADeadEndOne() {
        assertEquals(List.of(Compass.EAST, Compass.SOUTH, Compass.WEST), tee.arms());
        assertEquals(JunctionKind.T_JUNCTION, tee.kind());
        assertEquals(List.of(Compass.NORTH), deadEnd.arms());
        assertEquals(JunctionKind.DEAD_END, deadEnd.kind());
    }

    @Test
    void theApproachZoneHoldsTheLanesComingInAndTheExitZoneTheLanesGoingOut() {
        List<Rect> approach = tee.approachZone();
        List<Rect> exit = tee.exitZone();

        // East arm: traffic towards the junction drives west, in the south half.
        assertTrue(inAny(approach, 115, 31.5));
        assertFalse(inAny(approach, 115, 28.5));
        assertTrue(inAny(exit, 115, 28.5));
        // South arm: traffic towards the junction drives north, in the west half.
        assertTrue(inAny(approach, 98.5, 45));
        assertTrue(inAny(exit, 101.5, 45));
        // Zones end 23 m out along each arm.
        assertFalse(inAny(approach, 124, 31.5));
        assertTrue(inAny(approach, 100, 30), "the square belongs to both zones");
    }

    @Test
    void exitPointsAreOnTheOutgoingLaneCentreBeyondTheSquare() {
        assertEquals(new Vec2(104.5, 28.5), tee.exitPoint(Compass.EAST, 1.5));
        assertEquals(new Vec2(101.5, 34.5), tee.exitPoint(Compass.SOUTH, 1.5));
        assertEquals(new Vec2(95.5, 31.5), tee.exitPoint(Compass.WEST, 1.5));
    }

    private static boolean inAny(List<Rect> zone, double x, double y) {
        return zone.stream().anyMatch(r -> r.contains(x, y));
    }
}
