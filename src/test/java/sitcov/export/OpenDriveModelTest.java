package sitcov.export;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import sitcov.geom.Vec2;

/** The test's own reading of OpenDRIVE geometry, checked on hand-worked figures before it judges the export. */
class OpenDriveModelTest {
    private static final String LEFT_TURN = """
            <OpenDRIVE><header/>
              <road id="7" junction="3" length="4.71238898" rule="LHT">
                <planView><geometry s="0" x="10" y="20" hdg="0" length="4.71238898"><arc curvature="0.333333333333"/></geometry></planView>
                <lanes><laneSection s="0"><left><lane id="1" type="driving"><width sOffset="0" a="3" b="0" c="0" d="0"/></lane></left>
                  <center><lane id="0" type="none"/></center></laneSection></lanes>
              </road>
              <road id="8" junction="-1" length="10">
                <planView><geometry s="0" x="0" y="0" hdg="1.5707963267948966" length="10"><line/></geometry></planView>
                <lanes><laneOffset s="0" a="0.5" b="0" c="0" d="0"/><laneSection s="0">
                  <left><lane id="1" type="driving"><width sOffset="0" a="3" b="0" c="0" d="0"/></lane></left>
                  <right><lane id="-1" type="driving"><width sOffset="0" a="2" b="0.1" c="0" d="0"/></lane></right>
                </laneSection></lanes>
              </road>
            </OpenDRIVE>
            """;

    @Test
    void aQuarterCircleOfRadiusThreeTurningLeftEndsThreeAheadAndThreeToTheLeftFacingLeft() {
        OpenDriveModel.Road turn = OpenDriveModel.parse(LEFT_TURN).roads().get("7");
        assertClose(new Vec2(13, 23), turn.end());
        assertEquals(Math.PI / 2, turn.heading(turn.length()), 1e-9);
        // half way round: 3 (1 − cos 45°) to the left, 3 sin 45° ahead
        assertClose(new Vec2(10 + 3 * Math.sqrt(0.5), 20 + 3 - 3 * Math.sqrt(0.5)), turn.point(turn.length() / 2, 0));
        // the lane centre 1.5 m to the left runs on the inner circle, radius 1.5 about (10, 23)
        assertClose(new Vec2(11.5, 23), turn.point(turn.length(), turn.laneCentre(1, turn.length())));
        assertTrue(turn.drivenAlongReference(1), "LHT: the left lane is driven along the reference line");
    }

    @Test
    void locatingAPointOnAnArcGivesTheDistanceAlongItAndTheOffsetToTheLeft() {
        OpenDriveModel.Geometry g = OpenDriveModel.parse(LEFT_TURN).roads().get("7").geometry().get(0);
        double[] st = g.locate(new Vec2(11.5, 23));
        assertEquals(g.length(), st[0], 1e-6);
        assertEquals(1.5, st[1], 1e-6);
        OpenDriveModel.Geometry right = new OpenDriveModel.Geometry(0, 0, 0, 0, 3 * Math.PI / 2, "arc", -1.0 / 3);
        assertClose(new Vec2(3, -3), right.point(right.length(), 0));
        double[] outer = right.locate(new Vec2(4.5, -3));
        assertEquals(right.length(), outer[0], 1e-6);
        assertEquals(1.5, outer[1], 1e-6, "on a right turn the lane to the left runs on the outer circle");
    }

    @Test
    void laneCentresAddTheLaneOffsetAndTheWidthsInsideThemAndRhtDrivesTheRightLanesAlongTheLine() {
        OpenDriveModel.Road road = OpenDriveModel.parse(LEFT_TURN).roads().get("8");
        assertEquals(0.5 + 1.5, road.laneCentre(1, 0), 1e-12);
        assertEquals(0.5 - (2 + 0.1 * 4) / 2, road.laneCentre(-1, 4), 1e-12);
        assertClose(new Vec2(-2, 4), road.point(4, road.laneCentre(1, 4)));
        assertFalse(road.drivenAlongReference(1), "no rule means RHT, where lane 1 is driven against the line");
        assertClose(new Vec2(0, -1), road.drivingDirection(1, 0));
    }

    private static void assertClose(Vec2 expected, Vec2 actual) {
        assertTrue(expected.distanceTo(actual) < 1e-6, "expected " + expected + ", got " + actual);
    }
}
