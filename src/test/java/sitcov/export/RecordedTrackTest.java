package sitcov.export;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Set;
import org.junit.jupiter.api.Test;
import org.w3c.dom.Element;
import sitcov.builtin.BuiltinCar;
import sitcov.faults.Fault;
import sitcov.world.MapGenerator;

/**
 * A recorded trajectory turns a vehicle in a player as it turned in sitcov: a player moves a vehicle along a
 * trajectory by the distance covered and turns it by the headings of the vertices it passes, so a trajectory must
 * never hold two vertices at one place with two headings, and each vehicle asks esmini to take each vertex's
 * heading rather than blend the segments either side (src/main/java/sitcov/export/README.md, "A recorded run").
 */
class RecordedTrackTest {
    @Test
    void noTrajectoryTurnsAVehicleWithoutMovingItAndEveryFollowerAsksForTheVerticesHeadings() {
        // map 21 with fault 2: its moving cars turn on the spot hundreds of times (and turn while creeping)
        String document = OpenScenario.recording(RunRecording.of(MapGenerator.generate(21), 21,
                Set.of(Fault.WAYPOINTS_NORTH_EAST), BuiltinCar.FACTORY), "map-21.xodr", ScenarioVersion.V1_1);
        Element root = Dom.parse(document);
        int vertices = 0;
        int nudged = 0;
        for (Element follow : Dom.descendants(root, "FollowTrajectoryAction")) {
            Element previous = null;
            for (Element vertex : Dom.descendants(follow, "WorldPosition")) {
                if (previous != null) {
                    boolean samePlace = Dom.text(vertex, "x").equals(Dom.text(previous, "x"))
                            && Dom.text(vertex, "y").equals(Dom.text(previous, "y"));
                    assertTrue(!samePlace || Dom.text(vertex, "h").equals(Dom.text(previous, "h")),
                            "two vertices at one place with two headings: " + Dom.describe(previous) + ", "
                                    + Dom.describe(vertex));
                    // a turn on the spot is a step of exactly a tenth of a millimetre east
                    if (Math.abs(Dom.number(vertex, "x") - Dom.number(previous, "x") - 1e-4) < 1e-9
                            && Dom.text(vertex, "y").equals(Dom.text(previous, "y"))) {
                        nudged++;
                    }
                }
                vertices++;
                previous = vertex;
            }
        }
        assertTrue(vertices > 1000 && nudged > 100, "map 21 with fault 2 no longer turns cars on the spot (" + nudged
                + " steps of one digit among " + vertices + " vertices): pick another run");
        ScenarioModel m = ScenarioModel.parse(document);
        for (String entity : m.entities().keySet()) {
            boolean follows = !m.eventsOf(entity).stream().allMatch(e -> e.trajectories().isEmpty());
            assertEquals(follows ? "segment" : null, m.properties().get(entity).get("plineInterpolation"), entity);
        }
    }

    @Test
    void aVertexAfterATurnOnTheSpotIsWrittenATenthOfAMillimetreEastOfThePlace() {
        KeptVertices.Vertex place = new KeptVertices.Vertex(0, 137_166, 8_447, -348);
        assertTrue(written(place, 137_166 * KeptVertices.NUDGES_A_UNIT).contains("x=\"137.166\" y=\"8.447\" h=\"-0.0348\""));
        assertTrue(written(place, 137_166 * KeptVertices.NUDGES_A_UNIT + 1).contains("x=\"137.1661\" y=\"8.447\""));
        assertTrue(written(new KeptVertices.Vertex(0, 99_999, 1_000, 0), 999_991).contains("x=\"99.9991\" y=\"1\""));
    }

    private static String written(KeptVertices.Vertex v, long xTenths) {
        Xml xml = new Xml().open("r");
        v.position(xml, xTenths);
        return xml.close().document();
    }
}
