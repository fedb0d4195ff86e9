package sitcov.export;

import java.util.ArrayList;
import java.util.List;
import sitcov.world.Dimensions;

/**
 * One vehicle of a recorded run as a maneuver group. Each stretch the vehicle spends on the map is
 * an event at its first tick: a teleport to where the stretch starts and a timed trajectory, a
 * vertex for each tick interpolation between vertices cannot give back ({@link KeptVertices}),
 * positions followed exactly. A moving car that leaves the map (to be replaced at a dead end later)
 * is teleported to a parking place of its own outside the world until it comes back: players such
 * as CARLA's ScenarioRunner know no way to hide a vehicle.
 */
final class RecordedTrack {
    /** Parking places lie in a row this far south of the world, this far apart. */
    private static final double PARKING_OFFSET = 20;

    private RecordedTrack() {
    }

    /** A stretch of consecutive samples on the map, first and last included. */
    record Stretch(int first, int last) {
    }

    static void maneuverGroup(Xml xml, RunRecording.Track track, ScenarioVersion version, int parkingIndex) {
        List<RunRecording.Sample> samples = track.samples();
        xml.open("ManeuverGroup", "maximumExecutionCount", "1", "name", track.entity());
        OpenScenario.actors(xml, track.entity());
        xml.open("Maneuver", "name", track.entity() + " as recorded");
        for (Stretch s : stretches(samples)) {
            String name = track.entity() + (s.first() == 0 ? " from the start" : " back at tick " + (s.first() - 1));
            xml.open("Event", "name", name, "priority", "parallel");
            xml.open("Action", "name", name + ": in place");
            RunRecording.Sample first = samples.get(s.first());
            xml.open("PrivateAction").open("TeleportAction");
            ScenarioParts.frontPose(xml, first.x(), first.y(), first.bearing(), track.length());
            xml.close().close();
            xml.close();
            if (s.last() > s.first()) {
                xml.open("Action", "name", name + ": as recorded");
                follow(xml, track, s, version);
                xml.close();
            }
            ScenarioParts.timeTrigger(xml, "StartTrigger", "at sample " + s.first(), s.first() * Dimensions.TICK_SECONDS);
            xml.close();
            if (s.last() < samples.size() - 1) {
                String away = track.entity() + " leaves the map at tick " + s.last();
                xml.open("Event", "name", away, "priority", "parallel");
                xml.open("Action", "name", away + ": parked outside the world");
                xml.open("PrivateAction").open("TeleportAction");
                ScenarioParts.centrePose(xml, -PARKING_OFFSET * (parkingIndex + 1), Dimensions.WORLD_HEIGHT + PARKING_OFFSET,
                        sitcov.geom.Compass.EAST.bearing());
                xml.close().close();
                xml.close();
                ScenarioParts.timeTrigger(xml, "StartTrigger", "at sample " + (s.last() + 1),
                        (s.last() + 1) * Dimensions.TICK_SECONDS);
                xml.close();
            }
        }
        xml.close();
        xml.close();
    }

    /** The maximal runs of samples on the map, in order. */
    static List<Stretch> stretches(List<RunRecording.Sample> samples) {
        List<Stretch> out = new ArrayList<>();
        int start = -1;
        for (int i = 0; i < samples.size(); i++) {
            boolean on = samples.get(i).active();
            if (on && start < 0) {
                start = i;
            }
            if (!on && start >= 0) {
                out.add(new Stretch(start, i - 1));
                start = -1;
            }
        }
        if (start >= 0) {
            out.add(new Stretch(start, samples.size() - 1));
        }
        return out;
    }

    private static void follow(Xml xml, RunRecording.Track track, Stretch stretch, ScenarioVersion version) {
        xml.open("PrivateAction").open("RoutingAction").open("FollowTrajectoryAction");
        boolean wraps = version.wrapsTrajectories();
        if (wraps) {
            xml.open("TrajectoryRef");
        }
        xml.open("Trajectory", "name", track.entity() + " from sample " + stretch.first(), "closed", "false");
        xml.open("Shape").open("Polyline");
        List<RunRecording.Sample> samples = track.samples().subList(stretch.first(), stretch.last() + 1);
        for (int i : KeptVertices.of(samples)) {
            RunRecording.Sample s = samples.get(i);
            xml.startLine().open("Vertex", "time", Xml.seconds((stretch.first() + i) * Dimensions.TICK_SECONDS));
            ScenarioParts.frontPose(xml, s.x(), s.y(), s.bearing(), track.length());
            xml.close().endLine();
        }
        xml.close().close().close();
        if (wraps) {
            xml.close();
        }
        xml.open("TimeReference");
        xml.empty("Timing", "domainAbsoluteRelative", "absolute", "scale", "1", "offset", "0");
        xml.close();
        xml.empty("TrajectoryFollowingMode", "followingMode", "position");
        xml.close().close().close();
    }
}
