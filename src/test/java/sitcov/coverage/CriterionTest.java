package sitcov.coverage;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import org.junit.jupiter.api.Test;
import sitcov.world.Layout;
import sitcov.world.Situations;

class CriterionTest {
    // straight road y = 50, dead ends at x = 23 and 177; start (40, 48.5) east-bound; Target (150, 48.5)
    private final Layout straight = Situations.straight(List.of(Situations.parkedInEastboundLane(0, 100)));

    @Test
    void targetToObstacleIsTheDistanceToTheNearestParkedCarCentre() {
        // parked car centred at (100, 48.325)
        assertEquals(Math.hypot(50, 0.175), Criterion.TARGET_TO_OBSTACLE.value(straight), 1e-9);
    }

    @Test
    void targetToObstacleIs200WithoutParkedCars() {
        assertEquals(200, Criterion.TARGET_TO_OBSTACLE.value(Situations.straight(List.of())), 0);
    }

    @Test
    void startToTargetIsTheStraightLineDistance() {
        assertEquals(110, Criterion.START_TO_TARGET.value(straight), 1e-9);
        // on the tee: start (40, 28.5), Target (101.5, 70)
        assertEquals(Math.hypot(61.5, 41.5), Criterion.START_TO_TARGET.value(Situations.tee()), 1e-9);
    }

    @Test
    void previousJunctionIsTheOneBehindTheTargetInItsLane() {
        // east-bound lane: the junction behind is the west dead end at (23, 50), not the east one at 27 m
        assertEquals(Math.hypot(127, 1.5), Criterion.PREVIOUS_JUNCTION_TO_TARGET.value(straight), 1e-9);
        // the tee's Target is in the branch's south-bound lane: behind it is the T at (100, 30)
        assertEquals(Math.hypot(1.5, 40), Criterion.PREVIOUS_JUNCTION_TO_TARGET.value(Situations.tee()), 1e-9);
    }

    @Test
    void thePaperGridPutsTheHandBuiltMapsInTheCellsWorkedOutByHand() {
        GridDefinition grid = GridDefinition.paper();
        // straight: C1 50 -> bin 5, C2 110 -> bin 2, C3 127 -> bin 5
        assertEquals((5 * 6 + 2) * 6 + 5, grid.cellOf(grid.values(straight)));
        // tee: C1 200 -> 5, C2 74.2 -> 1, C3 40.03 -> 4
        assertEquals((5 * 6 + 1) * 6 + 4, grid.cellOf(grid.values(Situations.tee())));
    }
}
