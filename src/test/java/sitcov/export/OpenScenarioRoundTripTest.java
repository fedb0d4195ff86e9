package sitcov.export;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static sitcov.export.Frame.HEADING_TOLERANCE;
import static sitcov.export.Frame.METRE_TOLERANCE;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.junit.jupiter.api.Test;
import sitcov.control.Vehicle;
import sitcov.export.ScenarioModel.Pose;
import sitcov.faults.Fault;
import sitcov.geom.Vec2;
import sitcov.judge.Simulator;
import sitcov.oracle.Accident;
import sitcov.oracle.AccidentType;
import sitcov.oracle.RunResult;
import sitcov.world.Dimensions;
import sitcov.world.MapGenerator;
import sitcov.world.ParkedCar;
import sitcov.world.StartPose;
import sitcov.world.WorldMap;

/**
 * The OpenSCENARIO export read back: every vehicle stands where sitcov has its footprint (the centre, the
 * heading), the ego is sent to the Target, and a recorded run's trajectories retrace the poses a watcher of
 * the same run saw tick by tick, with the run's accidents declared (README, the export's conventions).
 */
class OpenScenarioRoundTripTest {
    /** A run with both kinds of clash, short enough to check quickly: map 33, its own internal seed, fault 14. */
    private static final long CLASH_SEED = 33;
    private static final Fault CLASH_FAULT = Fault.TARGET_LANE_CHECK_SKIPPED;
    private static final double TICK_SECONDS = 0.2;

    @Test
    void everyVehicleOfASituationStandsAtTheCentreOfItsSitcovFootprintAndTheEgoHeadsForTheTarget() {
        Failures failures = new Failures();
        ExportSeeds.upTo(100).forEach(seed -> {
            WorldMap map = MapGenerator.generate(seed);
            for (ScenarioVersion v : ScenarioVersion.values()) {
                ScenarioModel m = ScenarioModel.parse(OpenScenario.situation(map, "map-" + seed + ".xodr", v));
                List<String> problems = new ArrayList<>(startProblems(map, m, v, "map-" + seed + ".xodr"));
                problems.addAll(goalProblems(map, m));
                for (String problem : problems) {
                    failures.add(seed, v + ": " + problem);
                }
            }
        });
        failures.assertNone("a situation's vehicles, Target and header match sitcov's map");
    }

    @Test
    void aRecordedRunRetracesThePosesOfEveryVehicleTickByTickAndDeclaresItsAccidents() {
        WorldMap map = MapGenerator.generate(CLASH_SEED);
        Watched watched = watch(map, CLASH_SEED, Set.of(CLASH_FAULT));
        RunResult run = watched.result();
        assertTrue(run.count(AccidentType.CLASHWITHOBSTACLE) > 0 && run.count(AccidentType.CLASHWITHOTHERCAR) > 0,
                "map " + CLASH_SEED + " with fault " + CLASH_FAULT.id() + " no longer clashes with a parked and a moving car"
                        + " (" + run.countsByType() + "): pick another run with both");
        RunRecording recording = RunRecording.of(map, CLASH_SEED, Set.of(CLASH_FAULT));
        assertEquals(run, recording.result(), "the recording is of the same run");
        Failures failures = new Failures();
        for (ScenarioVersion v : ScenarioVersion.values()) {
            ScenarioModel m = ScenarioModel.parse(OpenScenario.recording(recording, "map-33.xodr", v));
            List<String> problems = new ArrayList<>(startProblems(map, m, v, "map-33.xodr"));
            problems.addAll(trajectoryProblems(watched, m));
            problems.addAll(accidentProblems(watched, m));
            problems.forEach(p -> failures.add(CLASH_SEED, v + ": " + p));
        }
        failures.assertNone("a recorded run's document matches the run as watched");
    }

    // ---- the situation

    /** What differs in the header, the entities or where they start; the same for a situation and a recording. */
    private static List<String> startProblems(WorldMap map, ScenarioModel m, ScenarioVersion v, String roadFile) {
        List<String> problems = new ArrayList<>();
        int minor = switch (v) {
            case V1_0 -> 0;
            case V1_1 -> 1;
            case V1_2 -> 2;
            case V1_3 -> 3;
        };
        if (m.revMajor() != 1 || m.revMinor() != minor) {
            problems.add("the header says revision " + m.revMajor() + "." + m.revMinor());
        }
        if (!m.logicFile().equals(roadFile)) {
            problems.add("the road network is " + m.logicFile() + ", not " + roadFile);
        }
        Map<String, Expected> expected = expectedVehicles(map);
        if (!m.entities().keySet().equals(expected.keySet())) {
            problems.add("the entities are " + m.entities().keySet() + ", expected " + expected.keySet());
            return problems;
        }
        for (Map.Entry<String, Expected> e : expected.entrySet()) {
            ScenarioModel.Box box = m.entities().get(e.getKey());
            if (box.centreX() != 0 || box.centreY() != 0 || Math.abs(box.length() - e.getValue().length()) > 1e-9
                    || Math.abs(box.width() - e.getValue().width()) > 1e-9) {
                problems.add(e.getKey() + "'s bounding box is " + box + ", expected " + e.getValue().length() + " m × "
                        + e.getValue().width() + " m about (0, 0)");
            }
            Pose at = m.initial().get(e.getKey());
            String wrong = at == null ? "it has no Init position" : e.getValue().mismatch(at);
            if (wrong != null) {
                problems.add(e.getKey() + " starts wrong: " + wrong);
            }
        }
        return problems;
    }

    /** What differs in the ego's start speed and its goal (a situation's; a recording's ego follows its trajectory instead). */
    private static List<String> goalProblems(WorldMap map, ScenarioModel m) {
        List<String> problems = new ArrayList<>();
        Double egoSpeed = m.initialSpeed().get("ego");
        if (egoSpeed == null || egoSpeed != 0) {
            problems.add("the ego's initial speed is " + egoSpeed + ", expected 0");
        }
        Vec2 target = Frame.point(map.layout().target().orElseThrow().position());
        List<Pose> goals = new ArrayList<>(m.acquiredPositions());
        goals.addAll(m.reachConditions());
        if (m.acquiredPositions().isEmpty() || m.reachConditions().isEmpty()
                || goals.stream().anyMatch(g -> new Vec2(g.x(), g.y()).distanceTo(target) > METRE_TOLERANCE)) {
            problems.add("the ego's goal " + m.acquiredPositions() + " and stop " + m.reachConditions()
                    + " are not both the Target at " + target);
        }
        return problems;
    }

    /** Where a vehicle must stand: the centre of sitcov's footprint, the heading, and its size; {@code eitherWay} for a parked car. */
    private record Expected(Vec2 centre, double heading, boolean eitherWay, double length, double width) {
        static Expected of(StartPose pose, double length, double width) {
            // sitcov's own footprint, anchored at the front centre, gives the centre
            return new Expected(Frame.point(pose.footprint(length, width).centre()), Frame.heading(pose.heading().bearing()),
                    false, length, width);
        }

        /** Null when {@code p} is here, facing this way (exactly in (−π, π], as a start heading is a whole quarter turn). */
        String mismatch(Pose p) {
            double off = new Vec2(p.x(), p.y()).distanceTo(centre);
            double turn = eitherWay ? Math.min(Frame.angleBetween(p.h(), heading), Frame.angleBetween(p.h(), heading + Math.PI))
                    : Math.abs(p.h() - heading);
            if (off > METRE_TOLERANCE || turn > 1e-6) {
                return "at (" + p.x() + ", " + p.y() + ") h " + p.h() + ", expected " + centre + " h " + heading
                        + (eitherWay ? " (or opposite)" : "") + ": " + String.format("%.4f m, %.6f rad off", off, turn);
            }
            return null;
        }
    }

    private static Map<String, Expected> expectedVehicles(WorldMap map) {
        Map<String, Expected> out = new LinkedHashMap<>();
        out.put("ego", Expected.of(map.layout().carStart().orElseThrow(), Dimensions.AUTONOMOUS_CAR_LENGTH,
                Dimensions.AUTONOMOUS_CAR_WIDTH));
        for (ParkedCar p : map.layout().parkedCars()) {
            // a parked car's footprint is the same facing either way along its road
            out.put("parked" + p.id(), new Expected(Frame.point(p.footprint().centre()), Frame.heading(p.axis().bearing()),
                    true, Dimensions.CAR_LENGTH, Dimensions.CAR_WIDTH));
        }
        for (int i = 0; i < map.movingCars().size(); i++) {
            out.put("moving" + i, Expected.of(map.movingCars().get(i), Dimensions.CAR_LENGTH, Dimensions.CAR_WIDTH));
        }
        return out;
    }

    // ---- a recorded run

    /** A run as a watcher saw it: per tick, each vehicle's footprint centre and bearing, the ego first. */
    private record Watched(RunResult result, Map<String, List<double[]>> poses, Map<Integer, String> movingById) {
    }

    private static Watched watch(WorldMap map, long internalSeed, Set<Fault> faults) {
        Map<String, List<double[]>> poses = new LinkedHashMap<>();
        Map<Integer, String> movingById = new LinkedHashMap<>();
        RunResult result = Simulator.run(map, internalSeed, faults, (tick, run, detector) -> {
            record(poses, "ego", run.car());
            List<? extends Vehicle> moving = run.movingCars();
            for (int i = 0; i < moving.size(); i++) {
                record(poses, "moving" + i, moving.get(i));
                movingById.put(moving.get(i).id(), "moving" + i);
            }
        }).result();
        return new Watched(result, poses, movingById);
    }

    private static void record(Map<String, List<double[]>> poses, String name, Vehicle v) {
        Vec2 centre = v.footprint().centre();
        poses.computeIfAbsent(name, n -> new ArrayList<>()).add(new double[] {centre.x(), centre.y(), v.heading()});
    }

    private static List<String> trajectoryProblems(Watched watched, ScenarioModel m) {
        List<String> problems = new ArrayList<>();
        Set<String> names = new LinkedHashSet<>(watched.poses().keySet());
        if (!m.trajectories().keySet().containsAll(names)) {
            problems.add("trajectories are given for " + m.trajectories().keySet() + ", expected " + names);
            return problems;
        }
        long ticks = watched.result().ticks();
        for (String name : names) {
            List<Pose> vertices = m.trajectories().get(name);
            List<double[]> seen = watched.poses().get(name);
            if (vertices.size() != ticks + 1 || seen.size() != ticks) {
                problems.add(name + " has " + vertices.size() + " vertices for a run of " + ticks + " ticks (watched "
                        + seen.size() + "), expected the start and one a tick");
                continue;
            }
            Pose start = m.initial().get(name);
            for (int k = 0; k <= ticks; k++) {
                Pose v = vertices.get(k);
                // vertex k is the state after tick k − 1, at (k − 1 + 1) × 0.2 s; vertex 0 the start, at 0 s
                if (Math.abs(v.time() - k * TICK_SECONDS) > 1e-6) {
                    problems.add(name + "'s vertex " + k + " is at " + v.time() + " s, expected " + k * TICK_SECONDS);
                    break;
                }
                Vec2 centre;
                double heading;
                if (k == 0) {
                    centre = new Vec2(start.x(), start.y());
                    heading = start.h();
                } else {
                    double[] s = seen.get(k - 1);
                    centre = Frame.point(s[0], s[1]);
                    heading = Frame.heading(s[2]);
                }
                double off = new Vec2(v.x(), v.y()).distanceTo(centre);
                double turn = Frame.angleBetween(v.h(), heading);
                if (off > METRE_TOLERANCE || turn > HEADING_TOLERANCE || Math.abs(v.h()) > Math.PI + 1e-6) {
                    problems.add(String.format("%s's vertex at %.1f s (after tick %d) is (%.4f, %.4f) h %.6f, the run had it at"
                            + " (%.4f, %.4f) h %.6f: %.4f m, %.6f rad off", name, v.time(), k - 1, v.x(), v.y(), v.h(),
                            centre.x(), centre.y(), heading, off, turn));
                    break;
                }
            }
        }
        return problems;
    }

    private static List<String> accidentProblems(Watched watched, ScenarioModel m) {
        List<String> problems = new ArrayList<>();
        List<Accident> accidents = watched.result().accidents();
        Map<String, String> p = m.parameters();
        if (!String.valueOf(accidents.size()).equals(p.get("accidentCount"))) {
            problems.add("accidentCount is " + p.get("accidentCount") + ", the run had " + accidents.size());
            return problems;
        }
        List<Double> times = new ArrayList<>();
        for (int k = 1; k <= accidents.size(); k++) {
            Accident a = accidents.get(k - 1);
            String other = a.otherParty() < 0 ? "none"
                    : a.type() == AccidentType.CLASHWITHOBSTACLE ? "parked" + a.otherParty()
                    : watched.movingById().get(a.otherParty());
            Vec2 at = Frame.point(a.x(), a.y());
            double time = (a.tick() + 1) * TICK_SECONDS;
            times.add(time);
            String declared = p.get("accident" + k + "Type") + " tick " + p.get("accident" + k + "Tick") + " time "
                    + p.get("accident" + k + "Time") + " at (" + p.get("accident" + k + "X") + ", " + p.get("accident" + k + "Y")
                    + ") with " + p.get("accident" + k + "Other");
            boolean same = a.type().name().equals(p.get("accident" + k + "Type"))
                    && String.valueOf(a.tick()).equals(p.get("accident" + k + "Tick"))
                    && Math.abs(Double.parseDouble(p.get("accident" + k + "Time")) - time) < 1e-6
                    && new Vec2(Double.parseDouble(p.get("accident" + k + "X")), Double.parseDouble(p.get("accident" + k + "Y")))
                            .distanceTo(at) <= METRE_TOLERANCE
                    && other.equals(p.get("accident" + k + "Other"));
            if (!same) {
                problems.add("accident " + k + " is declared " + declared + ", the run had " + a.type() + " at tick " + a.tick()
                        + " (" + time + " s) at " + at + " with " + other);
            }
        }
        List<Double> events = m.eventTimes().get("accidents");
        if (events == null || events.size() != times.size()
                || !events.stream().map(t -> Math.round(t * 1e6)).toList().equals(times.stream().map(t -> Math.round(t * 1e6)).toList())) {
            problems.add("the accidents maneuver's events start at " + events + " s, the run's accidents were at " + times + " s");
        }
        return problems;
    }
}
