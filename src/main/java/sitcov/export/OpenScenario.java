package sitcov.export;

import java.util.ArrayList;
import java.util.List;
import sitcov.oracle.Accident;
import sitcov.oracle.AccidentType;
import sitcov.vehicles.Dynamics;
import sitcov.world.Dimensions;
import sitcov.world.Layout;
import sitcov.world.ParkedCar;
import sitcov.world.StartPose;
import sitcov.world.Target;
import sitcov.world.WorldMap;

/**
 * What stands and moves on an exported map, as an ASAM OpenSCENARIO XML document
 * (src/main/java/sitcov/export/README.md, "Export to OpenDRIVE and OpenSCENARIO"). A situation puts the car under
 * test at its start with
 * the Target as its goal (the scenario stops when it is reached), the parked cars where they stand
 * and the moving cars at their starts, driving off at sitcov's speed. A recording replays a run:
 * every vehicle follows its timed trajectory, and the run's accidents are declared as parameters
 * (and summed up in the header's description).
 */
public final class OpenScenario {
    private static final double TICK = Dimensions.TICK_SECONDS;

    private OpenScenario() {
    }

    public static String situation(WorldMap map, String roadFile, ScenarioVersion version) {
        Layout layout = map.layout();
        StartPose car = layout.carStart().orElseThrow(() -> noRun(map));
        Target target = layout.target().orElseThrow(() -> noRun(map));
        Xml xml = new Xml();
        xml.open("OpenSCENARIO");
        ScenarioParts.header(xml, version, "sitcov situation " + map.seed() + ": the car under test drives from its start"
                + " to the Target among " + layout.parkedCars().size() + " parked and " + map.movingCars().size()
                + " moving cars");
        ScenarioParts.context(xml, List.of(), roadFile);
        entities(xml, map);
        xml.open("Storyboard");
        xml.open("Init").open("Actions");
        place(xml, RunRecording.EGO, car, ScenarioParts.Kind.CAR_UNDER_TEST);
        parked(xml, layout);
        for (int i = 0; i < map.movingCars().size(); i++) {
            StartPose p = map.movingCars().get(i);
            xml.open("Private", "entityRef", RunRecording.movingName(i));
            teleport(xml, p.position().x(), p.position().y(), p.heading().bearing(), ScenarioParts.Kind.MOVING);
            // moving cars set off from a standstill and speed up by sitcov's acceleration to its top speed
            ScenarioParts.speed(xml, Dynamics.MAX_SPEED / TICK, "linear", "rate", Dynamics.ACCELERATION / TICK / TICK);
            xml.close();
        }
        xml.close().close();
        xml.open("Story", "name", "sitcov situation " + map.seed());
        xml.open("Act", "name", "drive to the Target");
        xml.open("ManeuverGroup", "maximumExecutionCount", "1", "name", "the car under test");
        actors(xml, RunRecording.EGO);
        xml.open("Maneuver", "name", "reach the Target");
        xml.open("Event", "name", "head for the Target", "priority", "parallel");
        xml.open("Action", "name", "acquire the Target");
        xml.open("PrivateAction").open("RoutingAction").open("AcquirePositionAction");
        ScenarioParts.targetPosition(xml, target);
        xml.close().close().close();
        xml.close();
        ScenarioParts.timeTrigger(xml, "StartTrigger", "at the start", 0);
        xml.close().close().close();
        ScenarioParts.timeTrigger(xml, "StartTrigger", "at the start", 0);
        xml.close().close();
        ScenarioParts.stopAtTargetOrTimeout(xml, target, Dynamics.TIMEOUT_TICKS * TICK);
        xml.close();
        xml.close();
        return xml.document();
    }

    public static String recording(RunRecording run, String roadFile, ScenarioVersion version) {
        WorldMap map = run.map();
        List<Accident> accidents = run.accidents();
        Xml xml = new Xml();
        xml.open("OpenSCENARIO");
        ScenarioParts.header(xml, version, "sitcov recorded run: " + runName(run) + "; " + run.result().outcome()
                + " after " + run.result().ticks() + " ticks" + (run.isCut() ? ", recorded to tick " + run.lastTick() : "")
                + "; " + (accidents.isEmpty() ? "no accident" : accidents.size() + (accidents.size() == 1
                ? " accident: " : " accidents, the first ") + describe(run, accidents.get(0))));
        ScenarioParts.context(xml, parameters(run), roadFile);
        entities(xml, map);
        xml.open("Storyboard");
        xml.open("Init").open("Actions");
        for (RunRecording.Track track : run.tracks()) {
            RunRecording.Sample first = track.samples().get(0);
            xml.open("Private", "entityRef", track.entity());
            teleport(xml, first.x(), first.y(), first.bearing(), ScenarioParts.Kind.of(track));
            xml.close();
        }
        parked(xml, map.layout());
        xml.close().close();
        xml.open("Story", "name", "sitcov run " + runName(run));
        xml.open("Act", "name", "what happened");
        for (int i = 0; i < run.tracks().size(); i++) {
            RecordedTrack.maneuverGroup(xml, run.tracks().get(i), version, i);
        }
        ScenarioParts.timeTrigger(xml, "StartTrigger", "at the start", 0);
        xml.close().close();
        xml.open("StopTrigger");
        xml.open("ConditionGroup");
        ScenarioParts.timeCondition(xml, run.isCut() ? "the recording ends" : "the run ended", run.seconds());
        xml.close();
        xml.close();
        xml.close();
        xml.close();
        return xml.document();
    }

    /** The accidents as scenario parameters: a player or a script can read them without parsing comments. */
    private static List<String[]> parameters(RunRecording run) {
        List<String[]> out = new ArrayList<>();
        out.add(new String[] {"sitcovExternalSeed", "string", Long.toString(run.map().seed())});
        out.add(new String[] {"sitcovInternalSeed", "string", Long.toString(run.internalSeed())});
        out.add(new String[] {"sitcovFaults", "string", faults(run)});
        out.add(new String[] {"sitcovOutcome", "string", run.result().outcome().name()});
        out.add(new String[] {"sitcovTicks", "integer", Long.toString(run.result().ticks())});
        out.add(new String[] {"sitcovLastTickRecorded", "integer", Long.toString(run.lastTick())});
        out.add(new String[] {"accidentCount", "integer", Integer.toString(run.accidents().size())});
        int n = 1;
        for (Accident a : run.accidents()) {
            String p = "accident" + n++;
            out.add(new String[] {p + "Type", "string", a.type().name()});
            out.add(new String[] {p + "Tick", "integer", Long.toString(a.tick())});
            out.add(new String[] {p + "Time", "double", Xml.seconds(AsamFrame.seconds(a.tick()))});
            out.add(new String[] {p + "X", "double", Xml.metres(AsamFrame.x(a.x()))});
            out.add(new String[] {p + "Y", "double", Xml.metres(AsamFrame.y(a.y()))});
            out.add(new String[] {p + "Other", "string", otherParty(run, a)});
        }
        return out;
    }

    /** The entity the accident involved besides the car under test, or "none". */
    static String otherParty(RunRecording run, Accident a) {
        if (a.otherParty() < 0) {
            return "none";
        }
        if (a.type() == AccidentType.CLASHWITHOBSTACLE) {
            return RunRecording.parkedName(a.otherParty());
        }
        return run.tracks().stream().filter(t -> t.sitcovId() == a.otherParty() && !t.entity().equals(RunRecording.EGO))
                .map(RunRecording.Track::entity).findFirst().orElse("vehicle " + a.otherParty());
    }

    static String describe(RunRecording run, Accident a) {
        String other = otherParty(run, a);
        return a.type().name() + (other.equals("none") ? "" : " with " + other) + " at tick " + a.tick() + " ("
                + Xml.fixed(AsamFrame.seconds(a.tick()), 1) + " s) at x=" + Xml.fixed(AsamFrame.x(a.x()), 2) + " y="
                + Xml.fixed(AsamFrame.y(a.y()), 2);
    }

    private static String runName(RunRecording run) {
        return "map " + run.map().seed() + ", internal seed " + run.internalSeed() + ", " + faults(run);
    }

    private static String faults(RunRecording run) {
        return run.faults().isEmpty() ? "fault-free" : "faults " + String.join(" ", run.faults().stream()
                .map(f -> Integer.toString(f.id())).sorted().toList());
    }

    private static void entities(Xml xml, WorldMap map) {
        xml.open("Entities");
        ScenarioParts.vehicle(xml, RunRecording.EGO, ScenarioParts.Kind.CAR_UNDER_TEST);
        for (ParkedCar p : map.layout().parkedCars()) {
            ScenarioParts.vehicle(xml, RunRecording.parkedName(p.id()), ScenarioParts.Kind.PARKED);
        }
        for (int i = 0; i < map.movingCars().size(); i++) {
            ScenarioParts.vehicle(xml, RunRecording.movingName(i), ScenarioParts.Kind.MOVING);
        }
        xml.close();
    }

    private static void parked(Xml xml, Layout layout) {
        for (ParkedCar p : layout.parkedCars()) {
            xml.open("Private", "entityRef", RunRecording.parkedName(p.id()));
            xml.open("PrivateAction").open("TeleportAction");
            ScenarioParts.parkedPose(xml, p.centre().x(), p.centre().y(), p.axis().bearing());
            xml.close().close();
            xml.close();
        }
    }

    private static void place(Xml xml, String entity, StartPose pose, ScenarioParts.Kind kind) {
        xml.open("Private", "entityRef", entity);
        teleport(xml, pose.position().x(), pose.position().y(), pose.heading().bearing(), kind);
        ScenarioParts.speed(xml, 0, "step", "time", 0);
        xml.close();
    }

    private static void teleport(Xml xml, double x, double y, double bearing, ScenarioParts.Kind kind) {
        xml.open("PrivateAction").open("TeleportAction");
        ScenarioParts.vehiclePose(xml, x, y, bearing, kind);
        xml.close().close();
    }

    static void actors(Xml xml, String entity) {
        xml.open("Actors", "selectTriggeringEntities", "false");
        xml.empty("EntityRef", "entityRef", entity);
        xml.close();
    }

    private static IllegalArgumentException noRun(WorldMap map) {
        return new IllegalArgumentException("map " + map.seed() + " has no Target or no start for the car, so there is"
                + " no scenario to export; export its roads alone");
    }
}
