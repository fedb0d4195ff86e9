package sitcov.export;

import java.util.ArrayList;
import java.util.List;
import sitcov.world.Dimensions;

/**
 * One vehicle of a recorded run as a maneuver group. Each stretch the vehicle spends on the map is
 * an event at its first tick with a timed trajectory: a vertex for each tick interpolation between
 * vertices cannot give back ({@link KeptVertices}), positions followed exactly. A player moves a vehicle along a
 * trajectory by the distance covered and turns it by the headings of the vertices it passes, so between two
 * vertices at one place it cannot turn: where a vehicle turned on the spot, the vertex after the turn is written
 * a tenth of a millimetre (the last digit written) east of the place, and a player turns it there. A moving car that
 * leaves the map (to be replaced at a dead end later) is teleported, standing, to a parking place
 * of its own outside the world, and teleported back where it re-enters: players such as CARLA's
 * ScenarioRunner know no way to hide a vehicle.
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
        ScenarioParts.Kind kind = ScenarioParts.Kind.of(track);
        xml.open("ManeuverGroup", "maximumExecutionCount", "1", "name", track.entity());
        OpenScenario.actors(xml, track.entity());
        xml.open("Maneuver", "name", track.entity() + " as recorded");
        for (Stretch s : stretches(samples)) {
            String name = track.entity() + (s.first() == 0 ? " from the start" : " back at tick " + (s.first() - 1));
            double start = triggerTime(s.first());
            if (s.first() > 0) {
                // a teleport of its own: in the trajectory's event it would contend with it for the car
                RunRecording.Sample first = samples.get(s.first());
                xml.open("Event", "name", name + ": in place", "priority", "parallel");
                xml.open("Action", "name", name + ": in place");
                xml.open("PrivateAction").open("TeleportAction");
                ScenarioParts.vehiclePose(xml, first.x(), first.y(), first.bearing(), kind);
                xml.close().close();
                xml.close();
                ScenarioParts.timeTrigger(xml, "StartTrigger", "at sample " + s.first(), start);
                xml.close();
            }
            if (s.last() > s.first()) {
                xml.open("Event", "name", name, "priority", "parallel");
                xml.open("Action", "name", name + ": as recorded");
                follow(xml, track, kind, s, version);
                xml.close();
                ScenarioParts.timeTrigger(xml, "StartTrigger", "at sample " + s.first(), start);
                xml.close();
            }
            if (s.last() < samples.size() - 1) {
                leave(xml, track.entity() + " leaves the map at tick " + s.last(), parkingIndex, triggerTime(s.last() + 1));
            }
        }
        xml.close();
        xml.close();
    }

    /**
     * When an event for sample {@code i} starts: half a tick early, since a player fires a time
     * condition only once time has passed it, which would miss the sample itself.
     */
    static double triggerTime(int sample) {
        return Math.max(0, sample * Dimensions.TICK_SECONDS - Dimensions.TICK_SECONDS / 2);
    }

    /** Off the map: to its own parking place outside the world, standing (a player's controller would drive it on). */
    private static void leave(Xml xml, String name, int parkingIndex, double time) {
        xml.open("Event", "name", name, "priority", "parallel");
        xml.open("Action", "name", name + ": parked outside the world");
        xml.open("PrivateAction").open("TeleportAction");
        ScenarioParts.worldPose(xml, -PARKING_OFFSET * (parkingIndex + 1), Dimensions.WORLD_HEIGHT + PARKING_OFFSET,
                sitcov.geom.Compass.EAST.bearing());
        xml.close().close();
        xml.close();
        xml.open("Action", "name", name + ": standing");
        ScenarioParts.speed(xml, 0, "step", "time", 0);
        xml.close();
        ScenarioParts.timeTrigger(xml, "StartTrigger", "at the time it left", time);
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

    private static void follow(Xml xml, RunRecording.Track track, ScenarioParts.Kind kind, Stretch stretch,
                               ScenarioVersion version) {
        xml.open("PrivateAction").open("RoutingAction").open("FollowTrajectoryAction");
        boolean wraps = version.wrapsTrajectories();
        if (wraps) {
            xml.open("TrajectoryRef");
        }
        xml.open("Trajectory", "name", track.entity() + " from sample " + stretch.first(), "closed", "false");
        xml.open("Shape").open("Polyline");
        List<RunRecording.Sample> samples = track.samples().subList(stretch.first(), stretch.last() + 1);
        long previousX = Long.MIN_VALUE;
        long previousY = Long.MIN_VALUE;
        long previousH = Long.MIN_VALUE;
        for (KeptVertices.Vertex v : KeptVertices.of(samples, kind)) {
            long tenths = Math.round((stretch.first() + v.sample()) * Dimensions.TICK_SECONDS * 10);
            xml.startLine().open("Vertex", "time", Xml.decimal(tenths, 1));
            // a player takes a car's heading from its path, so a car turning on the spot needs a step to turn
            // over: the smallest the digits can show, a tenth of a millimetre east
            long x = v.x() * KeptVertices.NUDGES_A_UNIT;
            if (x == previousX && v.y() == previousY && v.h() != previousH) {
                x++;
            }
            v.position(xml, x);
            xml.close().endLine();
            previousX = x;
            previousY = v.y();
            previousH = v.h();
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
