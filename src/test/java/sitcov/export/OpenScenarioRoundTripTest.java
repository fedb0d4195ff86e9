package sitcov.export;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static sitcov.export.Frame.HEADING_TOLERANCE;
import static sitcov.export.Frame.METRE_TOLERANCE;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.junit.jupiter.api.Test;
import sitcov.builtin.BuiltinCar;
import sitcov.builtin.BuiltinRuns;
import sitcov.control.Vehicle;
import sitcov.export.ScenarioModel.Pose;
import sitcov.faults.Fault;
import sitcov.geom.Vec2;
import sitcov.judge.Simulator;
import sitcov.oracle.Accident;
import sitcov.oracle.AccidentType;
import sitcov.oracle.RunResult;
import sitcov.vehicles.AutonomousCar;
import sitcov.vehicles.MovingCar;
import sitcov.world.Dimensions;
import sitcov.world.MapGenerator;
import sitcov.world.ParkedCar;
import sitcov.world.StartPose;
import sitcov.world.WorldMap;

/**
 * The OpenSCENARIO export read back: every vehicle stands where sitcov has its footprint (the centre, the
 * heading), the ego is sent to the Target, and a recorded run's trajectories, interpolated linearly between the
 * vertices kept, retrace the pose a watcher of the same run saw at every tick, vehicles off the map are teleported
 * off the world, and the run's accidents are declared as the events a player reports them by
 * (src/main/java/sitcov/export/README.md, "The frame").
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
        RunRecording recording = RunRecording.of(map, CLASH_SEED, Set.of(CLASH_FAULT), BuiltinCar.FACTORY);
        assertEquals(run, recording.result(), "the recording is of the same run");
        Failures failures = new Failures();
        for (ScenarioVersion v : ScenarioVersion.values()) {
            ScenarioModel m = ScenarioModel.parse(OpenScenario.recording(recording, "map-33.xodr", v));
            List<String> problems = new ArrayList<>(startProblems(map, m, v, "map-33.xodr"));
            problems.addAll(trajectoryProblems(watched, m));
            problems.addAll(accidentProblems(watched, m));
            problems.forEach(p -> failures.add(CLASH_SEED, v + ": " + p));
            if (!(v.minor() >= 2 ? m.variables() : m.parameters()).keySet().containsAll(m.reported().stream()
                    .map(ScenarioModel.Reported::variable).toList())) {
                failures.add(CLASH_SEED, v + ": the events set " + m.reported() + ", not all declared as "
                        + (v.minor() >= 2 ? "variables " + m.variables() : "parameters " + m.parameters()));
            }
        }
        failures.assertNone("a recorded run's document matches the run as watched");
    }

    @Test
    void recordingsOfFaultFreeRunsRetraceEveryVehicleIncludingThoseThatLeaveTheMapAndComeBack() {
        Failures failures = new Failures();
        int leaving = 0;
        for (long seed : ExportSeeds.runs(6).toArray()) {
            WorldMap map = MapGenerator.generate(seed);
            Watched watched = watch(map, seed, Set.of());
            leaving += (int) watched.samples().values().stream().filter(s -> s.stream().anyMatch(p -> p[3] == 0)).count();
            RunRecording recording = RunRecording.of(map, seed, Set.of(), BuiltinCar.FACTORY);
            ScenarioModel m = ScenarioModel.parse(OpenScenario.recording(recording, "map-" + seed + ".xodr", ScenarioVersion.V1_3));
            List<String> problems = new ArrayList<>(trajectoryProblems(watched, m));
            problems.addAll(accidentProblems(watched, m));
            for (String p : problems) {
                failures.add(seed, p);
            }
        }
        failures.assertNone("a fault-free run's recording matches the run as watched");
        assertTrue(leaving > 0, "some moving car leaves the map in these runs, so its teleports are checked");
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
            // the reference point is the rear axle (the standard's), so the box's centre lies ahead of it
            double rearAxle = e.getKey().equals(RunRecording.EGO) ? AutonomousCar.REAR_AXLE : MovingCar.REAR_AXLE;
            double ahead = rearAxle - e.getValue().length() / 2;
            if (Math.abs(box.centreX() - ahead) > 1e-9 || box.centreY() != 0
                    || Math.abs(box.length() - e.getValue().length()) > 1e-9
                    || Math.abs(box.width() - e.getValue().width()) > 1e-9) {
                problems.add(e.getKey() + "'s bounding box is " + box + ", expected " + e.getValue().length() + " m × "
                        + e.getValue().width() + " m about (" + ahead + ", 0)");
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
        if (m.reachConditions().isEmpty() || m.reachConditions().stream()
                .anyMatch(g -> new Vec2(g.x(), g.y()).distanceTo(target) > METRE_TOLERANCE)) {
            problems.add("the scenario stops at " + m.reachConditions() + ", not at the Target at " + target);
        }
        // the route ends on the centre of the Target's lane, level with the Target: at most half a lane from it
        List<Pose> route = m.routeWaypoints();
        Pose end = route.isEmpty() ? null : route.get(route.size() - 1);
        if (end == null || new Vec2(end.x(), end.y()).distanceTo(target) > Dimensions.LANE_WIDTH / 2 + METRE_TOLERANCE
                || !m.acquiredPositions().isEmpty()) {
            problems.add("the ego is sent along " + route + " and to " + m.acquiredPositions() + ", not along a route"
                    + " ending by the Target at " + target);
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

    /**
     * A run as a watcher saw it, per vehicle and sample (0 the start, k the state after tick k − 1, at k × 0.2 s):
     * the centre of its footprint and its bearing (sitcov frame), and 1 while it is on the map, 0 while not.
     */
    private record Watched(RunResult result, Map<String, List<double[]>> samples, Map<Integer, String> movingById) {
    }

    private static Watched watch(WorldMap map, long internalSeed, Set<Fault> faults) {
        Map<String, List<double[]>> samples = new LinkedHashMap<>();
        StartPose start = map.layout().carStart().orElseThrow();
        samples.put("ego", new ArrayList<>(List.of(sample(start, Dimensions.AUTONOMOUS_CAR_LENGTH, Dimensions.AUTONOMOUS_CAR_WIDTH))));
        for (int i = 0; i < map.movingCars().size(); i++) {
            samples.put("moving" + i, new ArrayList<>(List.of(sample(map.movingCars().get(i), Dimensions.CAR_LENGTH, Dimensions.CAR_WIDTH))));
        }
        Map<Integer, String> movingById = new LinkedHashMap<>();
        RunResult result = BuiltinRuns.run(map, internalSeed, faults, (tick, run, detector) -> {
            samples.get("ego").add(sample(run.car()));
            List<? extends Vehicle> moving = run.movingCars();
            for (int i = 0; i < moving.size(); i++) {
                samples.get("moving" + i).add(sample(moving.get(i)));
                movingById.put(moving.get(i).id(), "moving" + i);
            }
        }).result();
        return new Watched(result, samples, movingById);
    }

    private static double[] sample(StartPose pose, double length, double width) {
        Vec2 centre = pose.footprint(length, width).centre();
        return new double[] {centre.x(), centre.y(), pose.heading().bearing(), 1};
    }

    private static double[] sample(Vehicle v) {
        Vec2 centre = v.footprint().centre();
        return new double[] {centre.x(), centre.y(), v.heading(), v.isActive() ? 1 : 0};
    }

    private static List<String> trajectoryProblems(Watched watched, ScenarioModel m) {
        List<String> problems = new ArrayList<>();
        for (Map.Entry<String, List<double[]>> e : watched.samples().entrySet()) {
            String name = e.getKey();
            List<double[]> samples = e.getValue();
            if (samples.size() != watched.result().ticks() + 1) {
                throw new AssertionError(name + " was watched " + samples.size() + " times in a run of " + watched.result().ticks() + " ticks");
            }
            List<List<Pose>> segments = m.eventsOf(name).stream().flatMap(ev -> ev.trajectories().stream()).toList();
            String problem = vertexProblem(samples, segments);
            if (problem == null) {
                problem = sampleProblem(samples, segments);
            }
            if (problem == null) {
                problem = teleportProblem(samples, m.eventsOf(name));
            }
            if (problem != null) {
                problems.add(name + ": " + problem);
            }
        }
        return problems;
    }

    /** Null when every vertex is at the time of a sample, in order, where the vehicle was on the map then. */
    private static String vertexProblem(List<double[]> samples, List<List<Pose>> segments) {
        for (List<Pose> segment : segments) {
            double previous = -1;
            for (Pose v : segment) {
                long k = Math.round(v.time() / TICK_SECONDS);
                if (Math.abs(v.time() - k * TICK_SECONDS) > 1e-6 || k < 0 || k >= samples.size() || v.time() <= previous) {
                    return "a vertex at " + v.time() + " s is not at the next tick's time (0.2 s apart, up to "
                            + (samples.size() - 1) * TICK_SECONDS + " s)";
                }
                previous = v.time();
                double[] s = samples.get((int) k);
                if (s[3] == 0) {
                    return "a vertex at " + v.time() + " s places it while it was off the map";
                }
                String off = poseMismatch(v.x(), v.y(), v.h(), s);
                if (off != null) {
                    return "its vertex at " + v.time() + " s (after tick " + (k - 1) + ") " + off;
                }
                if (Math.abs(v.h()) > Math.PI + 1e-6) {
                    return "its vertex at " + v.time() + " s has h " + v.h() + ", outside (−π, π]";
                }
            }
        }
        return null;
    }

    /** Null when, at every sample it was on the map, a trajectory interpolated linearly between its vertices gives its pose; and none while it was off. */
    private static String sampleProblem(List<double[]> samples, List<List<Pose>> segments) {
        for (int k = 0; k < samples.size(); k++) {
            double t = k * TICK_SECONDS;
            List<Pose> holding = segments.stream().filter(seg -> !seg.isEmpty() && seg.get(0).time() <= t + 1e-6
                    && seg.get(seg.size() - 1).time() >= t - 1e-6).findFirst().orElse(null);
            double[] s = samples.get(k);
            if (s[3] == 0) {
                if (holding != null) {
                    return "a trajectory holds it at " + t + " s, while it was off the map";
                }
                continue;
            }
            if (holding == null) {
                return "no trajectory holds it at " + t + " s (after tick " + (k - 1) + "), when it was on the map";
            }
            int i = 0;
            while (holding.get(i).time() < t - 1e-6) {
                i++;
            }
            Pose b = holding.get(i);
            Pose a = i == 0 ? b : holding.get(i - 1);
            double f = b.time() == a.time() ? 1 : (t - a.time()) / (b.time() - a.time());
            double h = a.h() + f * Math.IEEEremainder(b.h() - a.h(), 2 * Math.PI);
            String off = poseMismatch(a.x() + f * (b.x() - a.x()), a.y() + f * (b.y() - a.y()), h, s);
            if (off != null) {
                return "between its vertices at " + a.time() + " and " + b.time() + " s, at " + t + " s (after tick " + (k - 1)
                        + ") it " + off.replaceFirst("^is", "would be");
            }
        }
        return null;
    }

    /**
     * Null when it is teleported off the world as it leaves the map, and into place wherever a trajectory starts
     * again. Such events start half a tick before the sample they are for (a player fires a time condition only once
     * time has passed it, which would miss the sample itself).
     */
    private static String teleportProblem(List<double[]> samples, List<ScenarioModel.Event> events) {
        for (int k = 1; k < samples.size(); k++) {
            if (samples.get(k)[3] == 0 && samples.get(k - 1)[3] == 1) {
                double t = k * TICK_SECONDS;
                boolean away = events.stream().anyMatch(ev -> Math.abs(ev.time() - (t - TICK_SECONDS / 2)) <= 1e-6
                        && ev.teleports().stream().anyMatch(OpenScenarioRoundTripTest::offTheWorld));
                if (!away) {
                    return "it left the map after tick " + (k - 1) + " but no event at " + t + " s teleports it off the world";
                }
            }
        }
        for (ScenarioModel.Event ev : events) {
            for (List<Pose> segment : ev.trajectories()) {
                Pose first = segment.get(0);
                if (first.time() > 0 && Math.abs(ev.time() - (first.time() - TICK_SECONDS / 2)) > 1e-6) {
                    return "its trajectory from " + first.time() + " s starts at " + ev.time() + " s, not half a tick before";
                }
                // the teleport into place is an event of its own at the same time
                boolean placed = events.stream().filter(other -> Math.abs(other.time() - ev.time()) <= 1e-6)
                        .flatMap(other -> other.teleports().stream())
                        .anyMatch(p -> new Vec2(p.x(), p.y()).distanceTo(new Vec2(first.x(), first.y())) <= METRE_TOLERANCE);
                if (first.time() > 0 && !placed) {
                    return "its trajectory from " + first.time() + " s starts with no teleport to its first vertex";
                }
            }
        }
        return null;
    }

    /** Whether a car of 5 m × 2 m centred here lies wholly outside the 200 m × 100 m world. */
    private static boolean offTheWorld(Pose p) {
        double reach = Math.hypot(Dimensions.CAR_LENGTH, Dimensions.CAR_WIDTH) / 2;
        return p.x() < -reach || p.x() > Dimensions.WORLD_WIDTH + reach || p.y() < -reach || p.y() > Dimensions.WORLD_HEIGHT + reach;
    }

    /** Null when (x, y, h), exported, is within a centimetre and the heading tolerance of the sample; else how far off. */
    private static String poseMismatch(double x, double y, double h, double[] sample) {
        Vec2 centre = Frame.point(sample[0], sample[1]);
        double heading = Frame.heading(sample[2]);
        double off = new Vec2(x, y).distanceTo(centre);
        double turn = Frame.angleBetween(h, heading);
        if (off > METRE_TOLERANCE || turn > HEADING_TOLERANCE) {
            return String.format("is at (%.4f, %.4f) h %.6f, the run had it at (%.4f, %.4f) h %.6f: %.4f m, %.6f rad off",
                    x, y, h, centre.x(), centre.y(), heading, off, turn);
        }
        return null;
    }

    /**
     * What differs between the run's accidents and the events the document reports them by: accident k is the event
     * setting {@code accident<k>}, named by its type and tick, waiting for the ego and the other party to touch from
     * half a tick before the last sample they were apart, or, with no other party, starting half a tick before the
     * sample it was seen at; the ego's properties count them.
     */
    private static List<String> accidentProblems(Watched watched, ScenarioModel m) {
        List<String> problems = new ArrayList<>();
        List<Accident> accidents = watched.result().accidents();
        String counted = m.properties().get("ego").get("sitcovAccidents");
        if (!String.valueOf(accidents.size()).equals(counted)) {
            problems.add("the ego's sitcovAccidents is " + counted + ", the run had " + accidents.size());
        }
        for (int k = 1; k <= accidents.size(); k++) {
            Accident a = accidents.get(k - 1);
            String other = a.otherParty() < 0 ? null
                    : a.type() == AccidentType.CLASHWITHOBSTACLE ? "parked" + a.otherParty()
                    : watched.movingById().get(a.otherParty());
            String variable = "accident" + k;
            List<ScenarioModel.Reported> events = m.reported().stream().filter(r -> r.variable().equals(variable)).toList();
            List<String> touching = other == null ? List.of() : List.of("ego", other);
            double time = (other == null ? a.tick() + 0.5 : a.tick() - 0.5) * TICK_SECONDS;
            boolean same = events.size() == 1 && events.get(0).touching().equals(touching)
                    && Math.abs(events.get(0).time() - time) < 1e-6
                    && events.get(0).name().startsWith(variable + ": " + a.type() + ", ego")
                    && events.get(0).name().contains(" at tick " + a.tick() + " ")
                    && events.get(0).name().contains(String.format(java.util.Locale.ROOT, " at x=%.2f y=%.2f",
                            Frame.point(a.x(), a.y()).x(), Frame.point(a.x(), a.y()).y()));
            if (!same) {
                problems.add("accident " + k + " is reported by " + events + ", the run had " + a.type() + " at tick "
                        + a.tick() + (other == null ? "" : " with " + other) + ", so an event at " + time + " s");
            }
        }
        return problems;
    }
}
