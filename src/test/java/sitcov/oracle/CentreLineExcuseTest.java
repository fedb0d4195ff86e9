package sitcov.oracle;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import sitcov.geom.Box;
import sitcov.geom.Vec2;
import sitcov.world.Axis;
import sitcov.world.Layout;
import sitcov.world.ParkedCar;
import sitcov.world.RoadNetwork;
import sitcov.world.Situations;

/**
 * Being over the centre line is excused from geometry alone. Footprints are placed by hand on the
 * straight road (y = 50, surface y ∈ [47, 53], the east-bound lane the north half y &lt; 50, dead-end
 * squares x ∈ [20, 26] and [174, 180]) and on the T (main road y = 30, branch south along x = 100,
 * T-junction square x ∈ [97, 103], y ∈ [27, 33]). The car is 2 m × 2 m behind its front centre, so
 * the middle of its footprint is 1 m behind the front. A parked car is 5 m long.
 */
class CentreLineExcuseTest {

    /** A parked car against the north kerb at x = 100: x ∈ [97.5, 102.5], in the east-bound lane. */
    private static final ParkedCar IN_EASTBOUND_LANE = Situations.parkedInEastboundLane(0, 100);

    // ---- the lane is judged from the footprint ----

    @Test
    void theLaneAFootprintDrivesIsTheOneItsHeadingPointsAlong() {
        CentreLine centreLine = new CentreLine(network(List.of()));

        // front centre (60, 51.5): body y ∈ [50.5, 52.5], wholly in the south (west-bound) half
        assertTrue(centreLine.isOver(Box.behind(60, 51.5, 90, 2, 2)), "facing east in the west-bound half");
        assertFalse(centreLine.isOver(Box.behind(60, 51.5, 270, 2, 2)), "facing west in the west-bound half");
        // turned 30° off east towards the line (nearest compass direction still east), its corners
        // at y ≈ 47.13, 48.13, 48.87 and 49.87: all in the north half
        assertFalse(centreLine.isOver(Box.behind(60, 48, 120, 2, 2)));
    }

    @Test
    void aCarTurnedSharplyAcrossItsRoadIsStillJudgedAgainstThatRoad() {
        CentreLine centreLine = new CentreLine(network(List.of()));
        // bearing 135°, north-east: nearer north than east, but on an east–west road it drives the
        // east-bound lane; front (60, 51.5), corners at y ≈ 50.79 and 52.21 in the south half
        assertTrue(centreLine.isOver(Box.behind(60, 51.5, 135, 2, 2)));
        // the same heading with the body wholly in the north half (corners y ≈ 47.09 … 49.92)
        assertFalse(centreLine.isOver(Box.behind(60, 47.8, 135, 2, 2)));
    }

    // ---- passing an obstacle ----

    @Test
    void aFootprintOverTheLineBesideAParkedCarInItsLaneIsExcused() {
        CentreLineExcuse excuse = excuse(List.of(IN_EASTBOUND_LANE));
        // front (101, 50.5): body x ∈ [99, 101], y ∈ [49.5, 51.5] — beside the parked car, over the line
        Box beside = Box.behind(101, 50.5, 90, 2, 2);

        assertTrue(new CentreLine(network(List.of(IN_EASTBOUND_LANE))).isOver(beside));
        assertTrue(excuse.isPassingObstacle(beside));
        assertTrue(excuse.applies(beside));
    }

    @Test
    void theSameFootprintFarFromAnyObstacleIsNotExcused() {
        // the footprint's middle at x = 140, 37.5 m past the parked car's far end (x = 102.5)
        Box later = Box.behind(141, 50.5, 90, 2, 2);

        assertTrue(new CentreLine(network(List.of(IN_EASTBOUND_LANE))).isOver(later));
        assertFalse(excuse(List.of(IN_EASTBOUND_LANE)).applies(later));
        assertFalse(excuse(List.of()).applies(Box.behind(101, 50.5, 90, 2, 2)), "no parked car at all");
    }

    @Test
    void pullingOutIsExcusedFromTwelveMetresBeforeTheObstacle() {
        CentreLineExcuse excuse = excuse(List.of(IN_EASTBOUND_LANE));
        double nearEnd = 97.5;

        // the footprint's middle 11.5 m short of the near end is excused, 12.5 m short is not
        assertTrue(excuse.isPassingObstacle(Box.behind(nearEnd - 11.5 + 1, 50.5, 90, 2, 2)));
        assertFalse(excuse.isPassingObstacle(Box.behind(nearEnd - 12.5 + 1, 50.5, 90, 2, 2)));
    }

    @Test
    void pullingBackInIsExcusedUpToThirteenMetresPastTheObstacle() {
        CentreLineExcuse excuse = excuse(List.of(IN_EASTBOUND_LANE));
        double farEnd = 102.5;

        // the footprint's middle 12.5 m past the far end is excused, 13.5 m past is not
        assertTrue(excuse.isPassingObstacle(Box.behind(farEnd + 12.5 + 1, 50.5, 90, 2, 2)));
        assertFalse(excuse.isPassingObstacle(Box.behind(farEnd + 13.5 + 1, 50.5, 90, 2, 2)));
    }

    @Test
    void aGapOfUpToTwentyEightMetresInARowIsDrivenOnTheWrongSide() {
        // parked cars at x ∈ [97.5, 102.5] and, 27 m on, [129.5, 134.5]: in the middle of the gap
        // (x = 116) the footprint is 13.5 m from each, beyond either distance alone
        List<ParkedCar> row = List.of(IN_EASTBOUND_LANE, Situations.parkedInEastboundLane(1, 132));
        assertTrue(excuse(row).isPassingObstacle(Box.behind(117, 50.5, 90, 2, 2)));
        // with the second car 2 m farther on, the gap is 29 m
        List<ParkedCar> wider = List.of(IN_EASTBOUND_LANE, Situations.parkedInEastboundLane(1, 134));
        assertFalse(excuse(wider).isPassingObstacle(Box.behind(117.5, 50.5, 90, 2, 2)));
    }

    @Test
    void aParkedCarInTheOtherLaneExcusesNothing() {
        // against the south kerb at x = 100: in the west-bound lane
        ParkedCar inWestboundLane = new ParkedCar(0, 0, new Vec2(100, 50 + 1.675), Axis.EAST_WEST);
        CentreLineExcuse excuse = excuse(List.of(inWestboundLane));

        // driving east, over the line, its middle 6.5 m past it
        assertFalse(excuse.applies(Box.behind(110, 50.5, 90, 2, 2)));
        // driving west (its lane the south half) over the line beside a car parked in the north half
        Box westbound = Box.behind(99, 49.5, 270, 2, 2);
        assertTrue(new CentreLine(network(List.of())).isOver(westbound));
        assertFalse(excuse(List.of(IN_EASTBOUND_LANE)).applies(westbound));
    }

    @Test
    void aheadAndPastAreMeasuredInTheDirectionTheFootprintFaces() {
        // a car parked in the west-bound lane, x ∈ [97.5, 102.5]; a west-bound car reaches its near
        // end (x = 102.5) first. Facing west the front is 1 m west of the footprint's middle.
        ParkedCar inWestboundLane = new ParkedCar(0, 0, new Vec2(100, 50 + 1.675), Axis.EAST_WEST);
        CentreLineExcuse excuse = excuse(List.of(inWestboundLane));

        assertTrue(excuse.isPassingObstacle(Box.behind(102.5 + 11.5 - 1, 49.5, 270, 2, 2)), "11.5 m short of it");
        assertFalse(excuse.isPassingObstacle(Box.behind(102.5 + 12.5 - 1, 49.5, 270, 2, 2)), "12.5 m short of it");
        assertTrue(excuse.isPassingObstacle(Box.behind(97.5 - 12.5 - 1, 49.5, 270, 2, 2)), "12.5 m past it");
        assertFalse(excuse.isPassingObstacle(Box.behind(97.5 - 13.5 - 1, 49.5, 270, 2, 2)), "13.5 m past it");
    }

    // ---- junctions ----

    @Test
    void insideAJunctionSquareIsExcused() {
        CentreLineExcuse excuse = excuse(List.of());
        // straddling the centre line inside the east dead-end square: body x ∈ [176, 178]
        assertTrue(excuse.isAtJunction(Box.behind(178, 50, 90, 2, 2)));
    }

    @Test
    void drivingUpToAJunctionSquareIsExcusedWithinHalfAMetreOfItOnly() {
        CentreLineExcuse excuse = excuse(List.of());
        // the east dead-end square begins at x = 174; body x ∈ [171.6, 173.6] is 0.4 m short of it
        assertTrue(excuse.isAtJunction(Box.behind(173.6, 50.5, 90, 2, 2)));
        // body x ∈ [171.4, 173.4]: 0.6 m short, beyond the margin — a car swerving over the line as
        // it drives up to a junction is not excused
        assertFalse(excuse.isAtJunction(Box.behind(173.4, 50.5, 90, 2, 2)));
        assertFalse(excuse.applies(Box.behind(173.4, 50.5, 90, 2, 2)));
        assertTrue(CentreLineExcuse.JUNCTION_MARGIN > 0.4 && CentreLineExcuse.JUNCTION_MARGIN < 0.6);
    }

    @Test
    void leavingAJunctionSquareIsExcusedUpToTwoMetresPastIt() {
        CentreLineExcuse excuse = excuse(List.of());
        CentreLine centreLine = new CentreLine(network(List.of()));
        // driving west away from the east dead-end square (x ≥ 174), over the line into the north
        // half: the body 1.5 m past the square (x ∈ [170.5, 172.5]) is excused, 2.5 m past is not
        Box justOut = Box.behind(170.5, 49.5, 270, 2, 2);
        Box fartherOut = Box.behind(169.5, 49.5, 270, 2, 2);

        assertTrue(centreLine.isOver(justOut));
        assertTrue(excuse.isAtJunction(justOut));
        assertTrue(centreLine.isOver(fartherOut));
        assertFalse(excuse.applies(fartherOut));
        // the same place facing the square, driving up to it, is not
        assertFalse(excuse.applies(Box.behind(172.5, 50.5, 90, 2, 2)));
    }

    @Test
    void aCarSwingingWideOutOfTheTIsExcusedWhilePartOfItIsInTheSquare() {
        Layout tee = Situations.tee();
        RoadNetwork network = RoadNetwork.of(tee);
        CentreLineExcuse excuse = new CentreLineExcuse(network, List.of());
        CentreLine centreLine = new CentreLine(network);
        // turning right out of the branch onto the main road, heading east-north-east (bearing
        // 120°, nearest east), front at (105, 30.4): two corners, (105.5, 31.27) and (103.77, 32.27),
        // lie south of the centre line in the west-bound half, while its rear-left corner
        // (102.77, 30.53) is still in the square
        Box swinging = Box.behind(105, 30.4, 120, 2, 2);

        assertTrue(centreLine.isOver(swinging));
        assertTrue(excuse.isAtJunction(swinging));
        // the same pose 20 m east of the junction is over the line and not excused
        Box later = Box.behind(125, 30.4, 120, 2, 2);
        assertTrue(centreLine.isOver(later));
        assertFalse(excuse.applies(later));
    }

    // ---- fixtures ----

    private static RoadNetwork network(List<ParkedCar> parked) {
        return RoadNetwork.of(Situations.straight(parked));
    }

    private static CentreLineExcuse excuse(List<ParkedCar> parked) {
        return new CentreLineExcuse(network(parked), parked);
    }
}
