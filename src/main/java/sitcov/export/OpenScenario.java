package sitcov.export;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import sitcov.oracle.Accident;
import sitcov.oracle.AccidentType;
import sitcov.vehicles.Dynamics;
import sitcov.world.Dimensions;
import sitcov.world.Layout;
import sitcov.world.ParkedCar;
import sitcov.world.RoadNetwork;
import sitcov.world.StartPose;
import sitcov.world.Target;
import sitcov.world.WorldMap;

/**
 * What stands and moves on an exported map, as an ASAM OpenSCENARIO XML document
 * (src/main/java/sitcov/export/README.md, "Export to OpenDRIVE and OpenSCENARIO"). A situation puts the car under
 * test at its start with
 * the route to the Target as its goal (the scenario stops when it is reached), the parked cars where they stand
 * and the moving cars at their starts, driving off at sitcov's speed. A recording replays a run:
 * every vehicle follows its timed trajectory, the run itself is told by the ego's properties, and its accidents
 * and contacts are declared as events a player reports when it sees them ({@link Declared}).
 */
public final class OpenScenario {
    private static final double TICK = Dimensions.TICK_SECONDS;
    /** How ScenarioRunner tells the ego vehicle, the one a user's agent drives. */
    private static final ScenarioParts.Declaration EGO_TYPE = property("type", "ego_vehicle");
    /**
     * Asks esmini to turn a vehicle on a trajectory to each vertex's own heading as it passes it, as the vehicle
     * was in sitcov; by default it blends the headings either side of a vertex, which lags a turn by half a tick's.
     */
    private static final ScenarioParts.Declaration SEGMENT_HEADINGS = property("plineInterpolation", "segment");

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
        ScenarioParts.context(xml, version, List.of(), roadFile);
        entities(xml, map, List.of(EGO_TYPE), List.of());
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
        route(xml, map, car, target);
        ScenarioParts.timeTrigger(xml, "StartTrigger", "at the start", 0);
        xml.close().close().close();
        ScenarioParts.timeTrigger(xml, "StartTrigger", "at the start", 0);
        xml.close().close();
        ScenarioParts.stopAtTargetOrTimeout(xml, target, Dynamics.TIMEOUT_TICKS * TICK, version);
        xml.close();
        xml.close();
        return xml.document();
    }

    public static String recording(RunRecording run, String roadFile, ScenarioVersion version) {
        return recording(run, Optional.empty(), roadFile, version);
    }

    /** A recording whose accident {@code found} found the run's fault: its event and the ego say so. */
    public static String recording(RunRecording run, Optional<Accident> found, String roadFile, ScenarioVersion version) {
        WorldMap map = run.map();
        List<Accident> accidents = run.accidents();
        List<Declared> declared = Declared.of(run, found);
        Optional<Declared> finding = declared.stream().filter(Declared::found).findFirst();
        Xml xml = new Xml();
        xml.open("OpenSCENARIO");
        ScenarioParts.header(xml, version, "sitcov recorded run: " + runName(run) + "; " + run.result().outcome()
                + " after " + run.result().ticks() + " ticks" + (run.isCut() ? ", recorded to tick " + run.lastTick() : "")
                + "; " + (accidents.isEmpty() ? "no accident" : accidents.size() + (accidents.size() == 1
                ? " accident: " : " accidents, the first ") + describe(run, accidents.get(0)))
                + finding.map(d -> "; the accident that found the fault: " + d.describe())
                .orElse(afterTheEnd(run, found).map(f -> "; the accident that found the fault: " + f).orElse("")));
        ScenarioParts.context(xml, version, DeclaredEvents.variables(declared), roadFile);
        entities(xml, map, egoProperties(run, finding, afterTheEnd(run, found)), List.of(SEGMENT_HEADINGS));
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
        DeclaredEvents.maneuverGroup(xml, declared, version);
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

    /** The ego's properties in a recording: the run, so that a player or a script reads it from the car it drove. */
    private static List<ScenarioParts.Declaration> egoProperties(RunRecording run, Optional<Declared> finding,
                                                                 Optional<String> foundAfterTheEnd) {
        List<ScenarioParts.Declaration> out = new ArrayList<>(List.of(EGO_TYPE, SEGMENT_HEADINGS));
        out.add(property("sitcovExternalSeed", Long.toString(run.map().seed())));
        out.add(property("sitcovInternalSeed", Long.toString(run.internalSeed())));
        out.add(property("sitcovFaults", faults(run)));
        out.add(property("sitcovOutcome", run.result().outcome().name()));
        out.add(property("sitcovTicks", Long.toString(run.result().ticks())));
        out.add(property("sitcovLastTickRecorded", Long.toString(run.lastTick())));
        out.add(property("sitcovAccidents", Integer.toString(run.accidents().size())));
        finding.ifPresent(d -> out.add(property("sitcovFoundBy", d.id())));
        foundAfterTheEnd.ifPresent(f -> out.add(property("sitcovFoundBy", f)));
        return out;
    }

    /**
     * The accident that found the fault, in words, where it falls after the recording's end (a run that times
     * out, recorded to a few seconds after its car stopped for good): no event of the file can show it.
     */
    private static Optional<String> afterTheEnd(RunRecording run, Optional<Accident> found) {
        return found.filter(a -> a.tick() > run.lastTick()).map(a -> a.type().name() + " at tick " + a.tick() + " ("
                + Xml.fixed(AsamFrame.seconds(a.tick()), 1) + " s), after the recording's end at tick " + run.lastTick()
                + ": the car under test stood still from then on");
    }

    private static ScenarioParts.Declaration property(String name, String value) {
        return new ScenarioParts.Declaration(name, "string", value);
    }

    /** The entity the accident involved besides the car under test, or "none". */
    static String otherParty(RunRecording run, Accident a) {
        if (a.otherParty() < 0) {
            return "none";
        }
        if (a.type() == AccidentType.CLASHWITHOBSTACLE) {
            return RunRecording.parkedName(a.otherParty());
        }
        return vehicleNamed(run, a.otherParty());
    }

    /** The entity of the moving car with sitcov id {@code id}. */
    static String vehicleNamed(RunRecording run, int id) {
        return run.tracks().stream().filter(t -> t.sitcovId() == id && !t.entity().equals(RunRecording.EGO))
                .map(RunRecording.Track::entity).findFirst().orElse("vehicle " + id);
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

    private static void entities(Xml xml, WorldMap map, List<ScenarioParts.Declaration> ego,
                                 List<ScenarioParts.Declaration> moving) {
        xml.open("Entities");
        ScenarioParts.vehicle(xml, RunRecording.EGO, ScenarioParts.Kind.CAR_UNDER_TEST, ego);
        for (ParkedCar p : map.layout().parkedCars()) {
            ScenarioParts.vehicle(xml, RunRecording.parkedName(p.id()), ScenarioParts.Kind.PARKED, List.of());
        }
        for (int i = 0; i < map.movingCars().size(); i++) {
            ScenarioParts.vehicle(xml, RunRecording.movingName(i), ScenarioParts.Kind.MOVING, moving);
        }
        xml.close();
    }

    /**
     * The ego's way to the Target: its route's waypoints, or, where no route along the lanes reaches the Target,
     * the Target alone, for the player to find a way.
     */
    private static void route(Xml xml, WorldMap map, StartPose car, Target target) {
        Optional<EgoRoute> route = EgoRoute.plan(RoadNetwork.of(map.layout()), car, target);
        xml.open("Action", "name", route.isPresent() ? "follow the route to the Target" : "acquire the Target");
        xml.open("PrivateAction").open("RoutingAction");
        if (route.isPresent()) {
            xml.open("AssignRouteAction").open("Route", "name", "to the Target", "closed", "false");
            for (EgoRoute.Waypoint w : route.get().waypoints()) {
                xml.open("Waypoint", "routeStrategy", "shortest");
                ScenarioParts.worldPose(xml, w.point().x(), w.point().y(), w.heading().bearing());
                xml.close();
            }
            xml.close().close();
        } else {
            xml.comment("no route along the lanes reaches the Target from the car's start");
            xml.open("AcquirePositionAction");
            ScenarioParts.targetPosition(xml, target);
            xml.close();
        }
        xml.close().close();
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
