package sitcov.export;

import java.util.List;
import sitcov.oracle.Accident;
import sitcov.world.Dimensions;

/**
 * One vehicle of a recorded run as a maneuver group: it follows its trajectory, a vertex a tick at
 * the tick's time, positions followed exactly; it is hidden while it is off the map (a moving car
 * that left waits to be replaced at a dead end) and shown again when it comes back. The car under
 * test's group also carries an event at each accident's time, named after the accident, so that a
 * player's log says what happened when it happens.
 */
final class RecordedTrack {
    private RecordedTrack() {
    }

    static void maneuverGroup(Xml xml, RunRecording.Track track, ScenarioVersion version, List<Accident> accidents,
                              RunRecording run) {
        xml.open("ManeuverGroup", "maximumExecutionCount", "1", "name", track.entity());
        OpenScenario.actors(xml, track.entity());
        xml.open("Maneuver", "name", track.entity() + " as recorded");
        xml.open("Event", "name", track.entity() + " follows its recorded path", "priority", "parallel");
        xml.open("Action", "name", track.entity() + " trajectory");
        xml.open("PrivateAction").open("RoutingAction").open("FollowTrajectoryAction");
        if (version.wrapsTrajectories()) {
            xml.open("TrajectoryRef");
        }
        trajectory(xml, track);
        if (version.wrapsTrajectories()) {
            xml.close();
        }
        xml.open("TimeReference");
        xml.empty("Timing", "domainAbsoluteRelative", "absolute", "scale", "1", "offset", "0");
        xml.close();
        xml.empty("TrajectoryFollowingMode", "followingMode", "position");
        xml.close().close().close();
        xml.close();
        ScenarioParts.timeTrigger(xml, "StartTrigger", "at the start", 0);
        xml.close();
        visibility(xml, track);
        xml.close();
        if (!accidents.isEmpty()) {
            xml.open("Maneuver", "name", "accidents");
            int n = 1;
            for (Accident a : accidents) {
                String name = "accident " + n++ + ": " + OpenScenario.describe(run, a);
                xml.open("Event", "name", name, "priority", "parallel");
                // the event is there to be logged at its time; showing the visible car changes nothing
                visibilityAction(xml, name, true);
                ScenarioParts.timeTrigger(xml, "StartTrigger", "at tick " + a.tick(), AsamFrame.seconds(a.tick()));
                xml.close();
            }
            xml.close();
        }
        xml.close();
    }

    private static void trajectory(Xml xml, RunRecording.Track track) {
        xml.open("Trajectory", "name", track.entity() + " recorded", "closed", "false");
        xml.open("Shape").open("Polyline");
        List<RunRecording.Sample> samples = track.samples();
        for (int i : KeptVertices.of(samples)) {
            RunRecording.Sample s = samples.get(i);
            xml.startLine().open("Vertex", "time", Xml.seconds(i * Dimensions.TICK_SECONDS));
            ScenarioParts.frontPose(xml, s.x(), s.y(), s.bearing(), track.length());
            xml.close().endLine();
        }
        xml.close().close().close();
    }

    /** An event at every change between on and off the map. */
    private static void visibility(Xml xml, RunRecording.Track track) {
        List<RunRecording.Sample> samples = track.samples();
        for (int i = 1; i < samples.size(); i++) {
            boolean now = samples.get(i).active();
            if (now != samples.get(i - 1).active()) {
                String name = track.entity() + (now ? " comes back at " : " leaves the map at ") + "tick " + (i - 1);
                xml.open("Event", "name", name, "priority", "parallel");
                visibilityAction(xml, name, now);
                ScenarioParts.timeTrigger(xml, "StartTrigger", "at tick " + (i - 1), i * Dimensions.TICK_SECONDS);
                xml.close();
            }
        }
    }

    private static void visibilityAction(Xml xml, String name, boolean visible) {
        xml.open("Action", "name", name);
        xml.open("PrivateAction");
        String v = Boolean.toString(visible);
        xml.empty("VisibilityAction", "graphics", v, "traffic", v, "sensors", v);
        xml.close().close();
    }
}
