package sitcov.export;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import org.junit.jupiter.api.Test;
import sitcov.builtin.BuiltinCar;
import sitcov.builtin.BuiltinRuns;
import sitcov.control.Vehicle;
import sitcov.faults.Fault;
import sitcov.geom.Box;
import sitcov.oracle.Accident;
import sitcov.oracle.AccidentType;
import sitcov.oracle.Blame;
import sitcov.oracle.RunResult;
import sitcov.world.MapGenerator;
import sitcov.world.WorldMap;

/**
 * A recorded run declares every contact sitcov's footprints had, each as the event a player reports it by: the car
 * under test's, as an accident or as a contact the blame rules excused, and those between other vehicles, which the
 * oracle does not judge; and it marks the accident that found the run's fault (src/main/java/sitcov/export/README.md,
 * "A recorded run").
 */
class DeclaredEventsTest {
    private static final double TICK_SECONDS = 0.2;

    /** A contact as a watcher of the run saw it begin: footprints apart at one tick's end, overlapping at the next. */
    private record Began(long tick, List<String> pair) {
    }

    @Test
    void everyContactOfTheCarUnderTestIsDeclaredWithWhatTheOracleMadeOfIt() {
        // fault 14 on map 60: the car is touched by a moving car in a way the blame rules excuse
        WorldMap map = MapGenerator.generate(60);
        Set<Fault> faults = Set.of(Fault.TARGET_LANE_CHECK_SKIPPED);
        List<Began> began = watch(map, 60, faults, true);
        RunRecording run = RunRecording.of(map, 60, faults, BuiltinCar.FACTORY);
        RunResult result = run.result();
        int excused = result.excusedContacts().values().stream().mapToInt(Integer::intValue).sum();
        assertTrue(excused > 0, "map 60 with fault 14 no longer has an excused contact (" + result.excusedContacts()
                + "): pick another run that has one");
        ScenarioModel m = ScenarioModel.parse(OpenScenario.recording(run, "map-60.xodr", ScenarioVersion.V1_3));
        List<ScenarioModel.Reported> contacts = m.reported().stream().filter(r -> !r.touching().isEmpty()).toList();
        assertEquals(began.size(), contacts.size(), "one event for each contact the car had: " + began + " against "
                + contacts);
        Map<Blame, Integer> kinds = new EnumMap<>(Blame.class);
        for (Began b : began) {
            ScenarioModel.Reported r = contacts.stream().filter(c -> c.touching().equals(b.pair())
                    && Math.abs(c.time() - (b.tick() - 0.5) * TICK_SECONDS) < 1e-6).findFirst()
                    .orElseThrow(() -> new AssertionError("no event waits for " + b + " from half a tick before the last"
                            + " sample they were apart: " + contacts));
            Optional<Accident> accident = result.accidents().stream().filter(a -> a.tick() == b.tick()
                    && (a.type() == AccidentType.CLASHWITHOBSTACLE || a.type() == AccidentType.CLASHWITHOTHERCAR)).findFirst();
            if (accident.isPresent()) {
                assertTrue(r.variable().startsWith("accident") && r.name().contains(": " + accident.get().type() + ", "),
                        "the contact at tick " + b.tick() + " was the accident " + accident.get() + ", reported by " + r);
            } else {
                Blame blame = java.util.Arrays.stream(Blame.values()).filter(k -> r.name().contains("(" + k.name() + ")"))
                        .findFirst().orElseThrow(() -> new AssertionError(r + " names no blame rule"));
                assertTrue(r.variable().startsWith("excused") && !blame.isAccident(), r.toString());
                kinds.merge(blame, 1, Integer::sum);
            }
        }
        assertEquals(result.excusedContacts(), kinds, "the excused contacts declared, by the rule that excused them");
    }

    @Test
    void contactsBetweenOtherVehiclesAreDeclaredAsNotJudgedByTheOracle() {
        // fault 19 on map 1: moving cars come to touch twice, away from the car under test
        WorldMap map = MapGenerator.generate(1);
        Set<Fault> faults = Set.of(Fault.ONCOMING_AT_HALF_SPEED);
        List<Began> began = watch(map, 1, faults, false);
        assertTrue(began.size() >= 2, "map 1 with fault 19 no longer has contacts between other vehicles (" + began
                + "): pick another run that has some");
        RunRecording run = RunRecording.of(map, 1, faults, BuiltinCar.FACTORY);
        ScenarioModel m = ScenarioModel.parse(OpenScenario.recording(run, "map-1.xodr", ScenarioVersion.V1_0));
        List<Began> declared = new ArrayList<>();
        for (ScenarioModel.Reported r : m.reported()) {
            if (r.variable().startsWith("contact")) {
                assertTrue(r.name().startsWith(r.variable() + ": contact the oracle does not judge, "), r.name());
                declared.add(new Began(Math.round(r.time() / TICK_SECONDS + 0.5), r.touching()));
            }
        }
        assertEquals(began, declared, "the contacts between other vehicles, as the events that report them");
        assertEquals("false", m.parameters().get("contact1"), "each event's parameter is false until it starts");
    }

    @Test
    void theAccidentThatFoundTheFaultIsMarkedOnTheEgoAndInItsEventAlone() {
        RunRecording run = RunRecording.of(MapGenerator.generate(33), 33, Set.of(Fault.TARGET_LANE_CHECK_SKIPPED),
                BuiltinCar.FACTORY);
        List<Accident> accidents = run.accidents();
        assertTrue(accidents.size() >= 2, "map 33 with fault 14 no longer has two accidents: pick another run");
        Accident second = accidents.get(1);
        ScenarioModel marked = ScenarioModel.parse(OpenScenario.recording(run, Optional.of(second), "map-33.xodr",
                ScenarioVersion.V1_2));
        assertEquals("accident2", marked.properties().get("ego").get("sitcovFoundBy"));
        List<String> found = marked.reported().stream().map(ScenarioModel.Reported::name)
                .filter(n -> n.endsWith("; it found the fault")).toList();
        assertEquals(1, found.size(), found.toString());
        assertTrue(found.get(0).startsWith("accident2: " + second.type() + ", ego") && found.get(0).contains(
                " at tick " + second.tick() + " ("), found.get(0));
        ScenarioModel plain = ScenarioModel.parse(OpenScenario.recording(run, "map-33.xodr", ScenarioVersion.V1_2));
        assertFalse(plain.properties().get("ego").containsKey("sitcovFoundBy"));
        assertTrue(plain.reported().stream().noneMatch(r -> r.name().contains("found")), plain.reported().toString());
    }

    /**
     * The contacts that began in the run, in order: the car under test's ({@code car}) with moving and parked cars,
     * or else those between other vehicles (two moving cars, or a moving and a parked car); each pair as the export
     * names them, the first of it the car or the moving car listed first.
     */
    private static List<Began> watch(WorldMap map, long internalSeed, Set<Fault> faults, boolean car) {
        List<Began> out = new ArrayList<>();
        Map<List<String>, Boolean> touching = new java.util.HashMap<>();
        BuiltinRuns.run(map, internalSeed, faults, (tick, run, detector) -> {
            List<String> names = new ArrayList<>();
            List<Box> bodies = new ArrayList<>();
            if (car) {
                names.add("ego");
                bodies.add(run.car().footprint());
            }
            List<? extends Vehicle> moving = run.movingCars();
            for (int i = 0; i < moving.size(); i++) {
                names.add("moving" + i);
                bodies.add(moving.get(i).isActive() ? moving.get(i).footprint() : null);
            }
            for (int p = 0; p < run.parkedBodies().size(); p++) {
                names.add("parked" + p);
                bodies.add(run.parkedBodies().get(p));
            }
            for (int i = 0; i < names.size(); i++) {
                for (int j = i + 1; j < names.size(); j++) {
                    boolean counts = car ? i == 0 : !names.get(i).startsWith("parked");
                    List<String> pair = List.of(names.get(i), names.get(j));
                    boolean now = counts && bodies.get(i) != null && bodies.get(j) != null && bodies.get(i).overlaps(bodies.get(j));
                    if (now && !touching.getOrDefault(pair, false)) {
                        out.add(new Began(tick, pair));
                    }
                    touching.put(pair, now);
                }
            }
        });
        out.sort(java.util.Comparator.comparingLong(Began::tick));
        return out;
    }
}
