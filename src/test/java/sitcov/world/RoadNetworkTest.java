package sitcov.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import sitcov.geom.Box;
import sitcov.geom.Compass;
import sitcov.geom.Rect;
import sitcov.geom.Vec2;

class RoadNetworkTest {
    private final RoadNetwork tee = RoadNetwork.of(Situations.tee());

    @Test
    void markingsAreCutWhereAJunctionSquareCrossesTheRoad() {
        List<Marking> mainRoad = tee.markings().stream().filter(m -> m.roadId() == 0).toList();
        // three lines, each cut by the dead ends at x 10..16 and 184..190 and the tee at 97..103
        assertEquals(6, mainRoad.size());
        assertTrue(mainRoad.stream().noneMatch(m -> m.strip().overlaps(new Rect(97, 27, 103, 33))));
        Marking centre = mainRoad.stream().filter(m -> m.kind() == MarkingKind.CENTRE).findFirst().orElseThrow();
        assertEquals(new Rect(16, 29.95, 97, 30.05), rounded(centre.strip()));
    }

    @Test
    void edgeLinesLieJustInsideTheKerbs() {
        Marking edge = tee.markings().stream()
                .filter(m -> m.roadId() == 0 && m.kind() == MarkingKind.EDGE).findFirst().orElseThrow();
        assertEquals(27.225, edge.strip().minY(), 1e-9);
        assertEquals(0.1, edge.strip().height(), 1e-9);
    }

    @Test
    void snappingToALaneGivesTheLaneCentreAndItsLegalDirection() {
        assertEquals(Optional.of(new StartPose(new Vec2(50, 31.5), Compass.WEST)), tee.snapToLane(50, 32.7));
        assertEquals(Optional.of(new StartPose(new Vec2(98.5, 60), Compass.NORTH)), tee.snapToLane(97.2, 60));
        assertEquals(Optional.empty(), tee.snapToLane(50, 50));
    }

    @Test
    void aParkedCarStandsAgainstTheNearerKerb() {
        Road road = Situations.tee().roads().get(0);
        assertEquals(new Vec2(60, 28.325), RoadNetwork.kerbsidePosition(road, 60, 29.9));
        assertEquals(new Vec2(60, 31.675), RoadNetwork.kerbsidePosition(road, 60, 30.0));
    }

    @Test
    void aFootprintIsOnTheRoadOnlyWhenNoPartSticksOut() {
        assertTrue(tee.isOnRoad(Box.behind(60, 28.5, 90, 5, 2)));
        assertTrue(tee.isOnRoad(Box.behind(100, 38, 0, 5, 2)), "turning into the branch");
        assertFalse(tee.isOnRoad(Box.behind(60, 27.5, 90, 5, 2)));
        assertFalse(tee.isOnRoad(Box.behind(50, 50, 90, 5, 2)));
    }

    @Test
    void pointQueriesFindRoadsAndJunctions() {
        assertEquals(1, tee.roadAt(100, 60).id());
        assertNull(tee.roadAt(50, 60));
        assertEquals(0, tee.junctionAt(102, 32).id());
        assertFalse(tee.isInJunction(110, 30));
    }

    private static Rect rounded(Rect r) {
        return new Rect(Dimensions.rounded(r.minX()), Dimensions.rounded(r.minY()),
                Dimensions.rounded(r.maxX()), Dimensions.rounded(r.maxY()));
    }
}
