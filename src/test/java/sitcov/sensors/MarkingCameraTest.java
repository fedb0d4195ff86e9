package sitcov.sensors;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import sitcov.geom.Compass;
import sitcov.world.Axis;
import sitcov.world.Layout;
import sitcov.world.Road;
import sitcov.world.RoadNetwork;
import sitcov.world.Situations;

/**
 * The road-marking camera on the straight road of {@link Situations#straight}: y = 50, surface
 * y ∈ [47, 53], north edge line y ∈ [47.225, 47.325], centre line y ∈ [49.95, 50.05], markings cut
 * by the dead-end squares to x ∈ [26, 174]. The east-bound lane centre is y = 48.5.
 *
 * <p>Every reported hit is a sample that lies inside a strip, so the lateral offset of each hit
 * lies within the strip's lateral extent; the estimate (a mean of such hits) does too. That is
 * what bounds the tolerances below: half a strip width (0.05 m), with a little slack.
 */
class MarkingCameraTest {
    private static final double TOLERANCE = 0.06;

    private static final MarkingCamera STRAIGHT = new MarkingCamera(RoadNetwork.of(Situations.straight(List.of())));

    @Test
    void aCarAtTheLaneCentreSeesTheEdgeLineToItsLeftAndTheCentreLineToItsRight() {
        LaneEstimate seen = STRAIGHT.look(60, 48.5, Compass.EAST, CameraSettings.STANDARD);

        // edge line: y ∈ [47.225, 47.325], so from y = 48.5 it is 1.175..1.275 m to the left;
        // its centre is 0.275 m from the kerb and the lane centre 1.5 m: −(1.5 − 0.275) = −1.225.
        // Seen at all: the 30° ray enters the strip at 1.175 / sin 30° = 2.35 m and leaves at
        // 2.55 m, and its sample at 2.5 m falls inside.
        assertTrue(seen.edgeSeen(), "edge line not seen: " + seen);
        assertEquals(-1.225, seen.edgeOffset(), TOLERANCE);
        // centre line: y ∈ [49.95, 50.05], 1.45..1.55 m to the right; the −30° ray crosses it
        // between 2.9 m and 3.1 m and samples it at 3.0 m.
        assertTrue(seen.centreSeen(), "centre line not seen: " + seen);
        assertEquals(1.5, seen.centreOffset(), TOLERANCE);
        assertEquals(0, seen.laneCentre(), TOLERANCE);
    }

    @Test
    void aCarOneMetreTowardsTheKerbFindsTheLaneCentreOneMetreToItsRight() {
        // at y = 47.5: edge line 0.175..0.275 m left (the 15° ray crosses it between 0.68 m and
        // 1.06 m, sample 1.0 m), centre line 2.45..2.55 m right (the −30° ray: 4.9..5.1 m, sample 5.0)
        LaneEstimate seen = STRAIGHT.look(60, 47.5, Compass.EAST, CameraSettings.STANDARD);

        assertTrue(seen.edgeSeen() && seen.centreSeen(), seen.toString());
        assertEquals(-0.225, seen.edgeOffset(), TOLERANCE);
        assertEquals(2.5, seen.centreOffset(), TOLERANCE);
        // (−0.225 + 1.225 + 2.5 − 1.5) / 2 = 1
        assertEquals(1, seen.laneCentre(), TOLERANCE);
    }

    @Test
    void aCarOneMetreTowardsTheCentreLineFindsTheLaneCentreOneMetreToItsLeft() {
        // at y = 49.5: edge line 2.175..2.275 m left (the 30° ray: 4.35..4.55 m, sample 4.5),
        // centre line 0.45..0.55 m right (the −30° ray: 0.9..1.1 m, sample 1.0)
        LaneEstimate seen = STRAIGHT.look(60, 49.5, Compass.EAST, CameraSettings.STANDARD);

        assertTrue(seen.edgeSeen() && seen.centreSeen(), seen.toString());
        assertEquals(-2.225, seen.edgeOffset(), TOLERANCE);
        assertEquals(0.5, seen.centreOffset(), TOLERANCE);
        assertEquals(-1, seen.laneCentre(), TOLERANCE);
    }

    @Test
    void theWestboundLaneIsSeenTheSameWayLookingWest() {
        // west-bound lane centre y = 51.5; heading west the kerb (south, y = 53) is on the left:
        // south edge line y ∈ [52.675, 52.775] is 1.175..1.275 m away, the centre line 1.45..1.55 m
        LaneEstimate seen = STRAIGHT.look(120, 51.5, Compass.WEST, CameraSettings.STANDARD);

        assertEquals(-1.225, seen.edgeOffset(), TOLERANCE);
        assertEquals(1.5, seen.centreOffset(), TOLERANCE);
        assertEquals(0, seen.laneCentre(), TOLERANCE);
    }

    @Test
    void inADeadEndSquareLookingOnTowardsTheRoadEndNothingIsSeen() {
        // 3 m before the road end at x = 180: the dead-end square x ∈ [174, 180] cuts the markings,
        // which end at x = 174, behind the car; every ray of the ±45° fan moves east (cos ≥ 0.707)
        LaneEstimate seen = STRAIGHT.look(177, 48.5, Compass.EAST, CameraSettings.STANDARD);

        assertEquals(LaneEstimate.NOTHING_SEEN, seen);
        assertEquals(0, seen.laneCentre());
    }

    @Test
    void raysStopWhereTheRoadEndsSoLinesBeyondAGapAreNotSeen() {
        // road A ends at x = 100, road B starts 1 m further on; the car stands 0.5 m before A's end.
        // A's own lines are out of reach: to get 1.175 m to the side a ray within 45° must travel
        // at least 1.175 m forwards, past x = 100 where A's strips end.
        // B's lines would be seen if rays went on: the 10° ray samples 7.0 m (inside its
        // 6.77..7.34 m crossing of the edge line) at x = 99.5 + 7.0·cos 10° = 106.4, on B.
        LaneEstimate seen = new MarkingCamera(twoRoads(101)).look(99.5, 48.5, Compass.EAST, CameraSettings.STANDARD);

        assertEquals(LaneEstimate.NOTHING_SEEN, seen);
    }

    @Test
    void withTheGapClosedTheLinesOfTheNextRoadAreSeen() {
        // the control for the test above: B starts exactly where A ends, the surface has no gap
        LaneEstimate seen = new MarkingCamera(twoRoads(100)).look(99.5, 48.5, Compass.EAST, CameraSettings.STANDARD);

        assertTrue(seen.edgeSeen() && seen.centreSeen(), seen.toString());
        assertEquals(0, seen.laneCentre(), TOLERANCE);
    }

    @Test
    void withNoLeftArcTheEdgeLineIsNotSeenButTheCentreLineStillIs() {
        // a 0° left arc leaves one ray on the left, straight along the lane, parallel to the edge
        // line 1.175 m away: it can never cross it
        CameraSettings noLeftArc = new CameraSettings(0, 45, 10, 0.5, 0.5, 0);

        LaneEstimate seen = STRAIGHT.look(60, 48.5, Compass.EAST, noLeftArc);

        assertFalse(seen.edgeSeen(), seen.toString());
        assertTrue(seen.centreSeen(), seen.toString());
        assertEquals(0, seen.laneCentre(), TOLERANCE);
    }

    @Test
    void withARangeOfOneMetreNeitherLineIsWithinReach() {
        // range 1 m: samples at 0.5, 1.0 and (one step beyond) 1.5 m. Within ±45° a sample 1.5 m
        // away is at most 1.5·sin 45° = 1.06 m to the side, short of the edge line (1.175 m) and
        // the centre line (1.45 m).
        CameraSettings shortSighted = new CameraSettings(45, 45, 1, 0.5, 0.5, 0);
        assertEquals(1.5, shortSighted.limit(), 1e-12);

        assertEquals(LaneEstimate.NOTHING_SEEN, STRAIGHT.look(60, 48.5, Compass.EAST, shortSighted));
    }

    @Test
    void aFanOfOnlyTwoRaysASideMissesTheThinStripsBetweenItsSamples() {
        // 45° steps: rays at 0° (parallel to the lines) and ±45° only. The 45° ray crosses the
        // edge line between 1.175/sin 45° = 1.66 m and 1.275/sin 45° = 1.80 m and the centre line
        // between 2.05 m and 2.19 m; samples every 0.5 m (1.5, 2.0, 2.5) fall on neither.
        CameraSettings coarse = new CameraSettings(45, 45, 10, 45, 0.5, 0);

        assertEquals(LaneEstimate.NOTHING_SEEN, STRAIGHT.look(60, 48.5, Compass.EAST, coarse));
    }

    @Test
    void theStandardSettingsSampleOneStepBeyondTheirRange() {
        // 10 m / 0.5 m = 20 steps, plus one beyond: 21 samples, the last at 10.5 m
        assertEquals(10.5, CameraSettings.STANDARD.limit(), 1e-12);
    }

    /** Road A (y = 50) from x = 20 to 100 and road B from {@code bStart} to 180, no junctions. */
    private static RoadNetwork twoRoads(double bStart) {
        Layout layout = Situations.layout(
                List.of(new Road(0, Axis.EAST_WEST, 50, 20, 100), new Road(1, Axis.EAST_WEST, 50, bStart, 180)),
                List.of(), List.of(), null, null);
        return RoadNetwork.of(layout);
    }
}
