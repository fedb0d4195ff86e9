package sitcov.oracle;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.junit.jupiter.api.Test;
import sitcov.builtin.BuiltinRuns;
import sitcov.control.Vehicle;
import sitcov.engine.SimState;
import sitcov.faults.FaultSwitchboard;
import sitcov.geom.Box;
import sitcov.geom.Compass;
import sitcov.geom.Vec2;
import sitcov.judge.Simulator;
import sitcov.vehicles.AutonomousCar;
import sitcov.vehicles.Dynamics;
import sitcov.vehicles.Scene;
import sitcov.world.Axis;
import sitcov.world.Junction;
import sitcov.world.Layout;
import sitcov.world.ParkedCar;
import sitcov.world.Road;
import sitcov.world.Situations;
import sitcov.world.StartPose;
import sitcov.world.Target;
import sitcov.world.WorldMap;

/**
 * The accident oracle. The autonomous car cannot be moved by script, so each accident type is
 * forced by where the car starts (its footprint at tick 0 is already in the accident state, and
 * one tick moves it at most 0.1 m and turns it at most 15°), and contrasted with legal runs. The
 * blame rules, which need a moving car to touch the autonomous car, are tested directly with
 * hand-placed vehicles against a real, moving autonomous car.
 *
 * <p>Geometry of the straight road: y = 50, surface y ∈ [47, 53], east-bound lane centre y = 48.5,
 * dead-end squares x ∈ [20, 26] and [174, 180]. The autonomous car is 2 m × 2 m behind its front.
 */
class AccidentDetectorTest {

    // ---- legal runs raise nothing ----

    @Test
    void aRunOnTheEmptyStraightRoadReachesTheTargetWithoutAccident() {
        RunResult result = BuiltinRuns.run(Situations.withoutTraffic(Situations.straight(List.of())), 1);

        assertEquals(Outcome.TARGET_REACHED, result.outcome());
        assertEquals(List.of(), result.accidents());
        // 110 m from x = 40 to 150 at no more than 2.5 m a tick takes at least 44 ticks
        assertTrue(result.ticks() >= 44 && result.ticks() < Dynamics.TIMEOUT_TICKS, "ticks " + result.ticks());
    }

    @Test
    void overtakingAParkedCarIsNotAnAccident() {
        // a parked car in the lane (x ∈ [87.5, 92.5]) between the start and the Target: passing it
        // over the centre line is justified, and the car must touch neither it nor the kerb
        RunResult result = BuiltinRuns.run(
                Situations.withoutTraffic(Situations.straight(List.of(Situations.parkedInEastboundLane(0, 90)))), 1);

        assertEquals(Outcome.TARGET_REACHED, result.outcome());
        assertEquals(List.of(), result.accidents());
    }

    @Test
    void aUTurnThroughTheDeadEndIsNotAnAccident() {
        // the Target is in the west-bound lane: the car must drive to the east dead end, turn
        // through its square (where crossing the centre line is justified) and come back
        Layout layout = straightFrom(new StartPose(new Vec2(40, 48.5), Compass.EAST), List.of(),
                new Target(new Vec2(100, 51.5), 0));

        RunResult result = BuiltinRuns.run(Situations.withoutTraffic(layout), 1);

        assertEquals(Outcome.TARGET_REACHED, result.outcome());
        assertEquals(List.of(), result.accidents());
    }

    @Test
    void passingAnOncomingCarInItsOwnLaneIsNotAnAccident() {
        WorldMap map = Situations.withTraffic(Situations.straight(List.of()),
                List.of(new StartPose(new Vec2(170, 51.5), Compass.WEST)));

        RunResult result = BuiltinRuns.run(map, 1);

        assertEquals(Outcome.TARGET_REACHED, result.outcome());
        assertEquals(List.of(), result.accidents());
    }

    // ---- each type is raised when the car is put in that state ----

    @Test
    void startingOnTopOfAParkedCarIsAClashWithThatObstacle() {
        // parked car 0: x ∈ [38.5, 43.5], y ∈ [47.325, 49.325]; the car: x ∈ [38, 40], y ∈ [47.5, 49.5]
        // — an overlap 1.5 m by 1.825 m that one tick cannot undo; on the road, in its own lane
        Layout layout = straightFrom(new StartPose(new Vec2(40, 48.5), Compass.EAST),
                List.of(Situations.parkedInEastboundLane(0, 41)), null);

        List<Accident> accidents = firstTicks(layout, 1);

        assertEquals(1, accidents.size(), accidents.toString());
        Accident clash = accidents.get(0);
        assertEquals(AccidentType.CLASHWITHOBSTACLE, clash.type());
        assertEquals(0, clash.tick());
        assertEquals(0, clash.otherParty());
        assertEquals("CLASHWITHOBSTACLE#0", clash.signature());
    }

    @Test
    void startingWithPartOfTheBodyOverTheKerbIsLeavingTheRoad() {
        // front centre on the kerb line y = 47: the body spans y ∈ [46, 48]. Turned by at most 15°
        // about the rear axle (1.5 m behind the front) and moved 0.1 m, its rear-left corner is
        // still at least cos 15° − 0.5·sin 15° − 0.1 = 0.74 m north of the kerb.
        Layout layout = straightFrom(new StartPose(new Vec2(40, 47), Compass.EAST), List.of(), null);

        List<Accident> accidents = firstTicks(layout, 1);

        assertEquals(1, accidents.size(), accidents.toString());
        assertEquals(AccidentType.LEAVEROAD, accidents.get(0).type());
        assertEquals(0, accidents.get(0).tick());
        assertEquals(-1, accidents.get(0).otherParty());
        assertEquals("LEAVEROAD", accidents.get(0).signature());
    }

    @Test
    void startingEastboundInTheWestboundLaneIsCrossingTheCentreLine() {
        // body y ∈ [50.5, 52.5]: wholly in the west-bound half, 0.5 m clear of the centre,
        // 24 m from either dead-end square, no parked car to overtake
        Layout layout = straightFrom(new StartPose(new Vec2(50, 51.5), Compass.EAST), List.of(), null);

        List<Accident> accidents = firstTicks(layout, 1);

        assertEquals(1, accidents.size(), accidents.toString());
        assertEquals(AccidentType.CROSSCENTRELINE, accidents.get(0).type());
        assertEquals(0, accidents.get(0).tick());
    }

    @Test
    void startingOverTheLineBehindAParkedCarInItsLaneIsPassingItNotAnAccident() {
        // the same footprint as above, with a car parked in the east-bound lane at x ∈ [57.5, 62.5]:
        // its near end is 8.5 m ahead of the footprint's middle (x = 49). At tick 0 the car has not
        // begun to overtake, so only the geometry can excuse it.
        Layout layout = straightFrom(new StartPose(new Vec2(50, 51.5), Compass.EAST),
                List.of(Situations.parkedInEastboundLane(0, 60)), null);

        assertEquals(List.of(), firstTicks(layout, 1));
    }

    @Test
    void startingOverTheLineWithTheParkedCarFarAheadIsCrossingTheCentreLine() {
        // the parked car at x ∈ [117.5, 122.5], 68.5 m ahead of the footprint's middle
        Layout layout = straightFrom(new StartPose(new Vec2(50, 51.5), Compass.EAST),
                List.of(Situations.parkedInEastboundLane(0, 120)), null);

        List<Accident> accidents = firstTicks(layout, 1);

        assertEquals(1, accidents.size(), accidents.toString());
        assertEquals(AccidentType.CROSSCENTRELINE, accidents.get(0).type());
    }

    @Test
    void anAccidentIsAnEventCountedWhenTheStateIsEnteredNotEveryTickItLasts() {
        // start off the road as above, then drive on to the Target; whatever the car does, the
        // LEAVEROAD events must be exactly the ticks at which its footprint went from on to off
        // the road, and they include tick 0
        Layout layout = straightFrom(new StartPose(new Vec2(40, 47), Compass.EAST), List.of(), null);
        List<Long> entered = new ArrayList<>();
        boolean[] wasOff = {false};

        RunResult result = BuiltinRuns.run(Situations.withoutTraffic(layout), 1, Set.of(),
                (tick, scene, detector) -> {
                    boolean off = !scene.network().isOnRoad(scene.car().footprint());
                    if (off && !wasOff[0]) {
                        entered.add(tick);
                    }
                    wasOff[0] = off;
                }).result();

        List<Long> events = result.accidents().stream()
                .filter(a -> a.type() == AccidentType.LEAVEROAD).map(Accident::tick).toList();
        assertEquals(entered, events);
        assertEquals(0L, events.get(0));
    }

    @Test
    void aTargetOnAnotherRoadIsNeverReachedAndTheRunTimesOutOnce() {
        // two parallel roads 40 m apart with no road between them: the car, which may not leave
        // its road, cannot come within 1.5 m of the Target. Ticks are numbered from 0, so the
        // 5000th and last is tick 4999.
        Layout layout = Situations.layout(
                List.of(new Road(0, Axis.EAST_WEST, 30, 20, 180), new Road(1, Axis.EAST_WEST, 70, 20, 180)),
                List.of(new Junction(0, new Vec2(23, 30), 0, 23, 0, 0), new Junction(1, new Vec2(177, 30), 0, 0, 0, 23),
                        new Junction(2, new Vec2(23, 70), 0, 23, 0, 0), new Junction(3, new Vec2(177, 70), 0, 0, 0, 23)),
                List.of(), new Target(new Vec2(100, 68.5), 1), new StartPose(new Vec2(40, 28.5), Compass.EAST));

        RunResult result = BuiltinRuns.run(Situations.withoutTraffic(layout), 1);

        assertEquals(Outcome.TIMEOUT, result.outcome());
        assertEquals(Dynamics.TIMEOUT_TICKS, result.ticks());
        assertEquals(1, result.count(AccidentType.TIMEOUT));
        Accident last = result.accidents().get(result.accidents().size() - 1);
        assertEquals(AccidentType.TIMEOUT, last.type());
        assertEquals(Dynamics.TIMEOUT_TICKS - 1, last.tick());
        assertEquals(-1, last.otherParty());
    }

    // ---- the centre line ----

    @Test
    void aFootprintIsOverTheCentreLineWhenACornerIsInTheOtherLaneOutsideJunctions() {
        CentreLine centreLine = new CentreLine(straightScene().network());

        // facing east (bearing 90), so its lane is the east-bound half; front centre y = 48.5: corners at y = 47.5 and 49.5, both in the east-bound half
        assertFalse(centreLine.isOver(Box.behind(60, 48.5, 90, 2, 2)));
        // front centre y = 49.2: corners at y = 50.2, 0.2 m into the west-bound half
        assertTrue(centreLine.isOver(Box.behind(60, 49.2, 90, 2, 2)));
        // corners exactly on the centre (y = 50) are not over it
        assertFalse(centreLine.isOver(Box.behind(60, 49, 90, 2, 2)));
        // straddling the centre inside the east dead-end square x ∈ [174, 180]: corners at x 176, 178
        assertFalse(centreLine.isOver(Box.behind(178, 50, 90, 2, 2)));
    }

    @Test
    void aFootprintTouchesThePaintedCentreLineOnlyWhenItOverlapsTheStrip() {
        CentreLine centreLine = new CentreLine(straightScene().network());

        // the strip is y ∈ [49.95, 50.05], x ∈ [26, 174]; a 5 m × 2 m car centred at y = 51.5
        // spans y ∈ [50.5, 52.5]; centred at y = 50.9 it reaches y = 49.9
        assertFalse(centreLine.touches(Box.centred(100, 51.5, 90, 5, 2)));
        assertTrue(centreLine.touches(Box.centred(100, 50.9, 90, 5, 2)));
        // inside a dead-end square the line is not painted
        assertFalse(centreLine.touches(Box.centred(177, 50, 90, 2, 2)));
    }

    // ---- blame ----

    @Test
    void blameRulesAreTriedInTheirDeclaredOrderAndOnlyTheLastIsAnAccident() {
        assertEquals(List.of(Blame.EXCUSED_STANDING_STILL, Blame.EXCUSED_HIT_FROM_BEHIND,
                Blame.EXCUSED_OTHER_ON_CENTRE_LINE, Blame.EXCUSED_OTHER_IN_WRONG_LANE, Blame.AT_FAULT),
                Arrays.asList(Blame.values()));
        for (Blame b : Blame.values()) {
            assertEquals(b == Blame.AT_FAULT, b.isAccident(), b.name());
        }
    }

    @Test
    void aCarStandingStillIsNeverToBlame() {
        Scene scene = straightScene(); // not stepped yet: speed 0
        AutonomousCar car = scene.autonomousCar();
        assertEquals(0, car.speed());
        CentreLine centreLine = new CentreLine(scene.network());
        // head-on in its lane while it is over the centre line: every other rule would blame it
        Vehicle oncoming = new Other(car.x() + 4, 48.5, 270, 1);

        assertEquals(Blame.EXCUSED_STANDING_STILL, BlameRules.judge(car, oncoming, centreLine, true));
    }

    @Test
    void aCarHitFromBehindByAFasterCarIsNotToBlame() {
        Scene scene = movingScene();
        AutonomousCar car = scene.autonomousCar();
        CentreLine centreLine = new CentreLine(scene.network());
        // 1 m behind its front (inside its body), same way, faster
        Vehicle faster = new Other(car.x() - 1, 48.5, 90, car.speed() + 0.5);
        assertEquals(Blame.EXCUSED_HIT_FROM_BEHIND, BlameRules.judge(car, faster, centreLine, false));
        // the excuse comes before the centre-line one: faster and on the centre line (y ∈ [49, 51])
        Vehicle fasterOnLine = new Other(car.x() - 1, 50, 90, car.speed() + 0.5);
        assertEquals(Blame.EXCUSED_HIT_FROM_BEHIND, BlameRules.judge(car, fasterOnLine, centreLine, false));
    }

    @Test
    void aSlowerCarBehindOrACarAheadInTheLaneIsTheCarsFault() {
        Scene scene = movingScene();
        AutonomousCar car = scene.autonomousCar();
        CentreLine centreLine = new CentreLine(scene.network());
        // both in the east-bound lane, y ∈ [47.5, 49.5], clear of the centre strip
        Vehicle slowerBehind = new Other(car.x() - 1, 48.5, 90, 0);
        Vehicle slowerAhead = new Other(car.x() + 4.5, 48.5, 90, 0);

        assertEquals(Blame.AT_FAULT, BlameRules.judge(car, slowerBehind, centreLine, false));
        assertEquals(Blame.AT_FAULT, BlameRules.judge(car, slowerAhead, centreLine, false));
    }

    @Test
    void theOtherCarOnTheCentreLineTakesTheBlame() {
        Scene scene = movingScene();
        AutonomousCar car = scene.autonomousCar();
        CentreLine centreLine = new CentreLine(scene.network());
        // oncoming, centred on the centre line: y ∈ [49, 51]
        Vehicle straddling = new Other(car.x() + 5, 50, 270, 1);

        assertEquals(Blame.EXCUSED_OTHER_ON_CENTRE_LINE, BlameRules.judge(car, straddling, centreLine, false));
    }

    @Test
    void aCarComingTheWrongWayInTheCarsLaneIsToBlameUnlessTheCarLeftItsLane() {
        Scene scene = movingScene();
        AutonomousCar car = scene.autonomousCar();
        CentreLine centreLine = new CentreLine(scene.network());
        // head-on in the east-bound lane, y ∈ [47.5, 49.5]: not on the centre strip
        Vehicle wrongWay = new Other(car.x() + 4, 48.5, 270, 1);

        assertEquals(Blame.EXCUSED_OTHER_IN_WRONG_LANE, BlameRules.judge(car, wrongWay, centreLine, false));
        assertEquals(Blame.AT_FAULT, BlameRules.judge(car, wrongWay, centreLine, true));
    }

    // ---- results ----

    @Test
    void countsByTypeHasEveryTypeInTypeOrder() {
        List<Accident> accidents = List.of(
                new Accident(3, AccidentType.LEAVEROAD, 1, 2, -1),
                new Accident(9, AccidentType.CLASHWITHOTHERCAR, 1, 2, 4),
                new Accident(12, AccidentType.LEAVEROAD, 1, 2, -1),
                new Accident(4999, AccidentType.TIMEOUT, 1, 2, -1));
        RunResult result = new RunResult(7, 8, Outcome.TIMEOUT, accidents, Map.of(Blame.EXCUSED_STANDING_STILL, 2), 5000);

        Map<AccidentType, Long> counts = result.countsByType();

        assertEquals(List.of(AccidentType.values()), new ArrayList<>(counts.keySet()));
        assertEquals(List.of(0L, 1L, 2L, 0L, 1L), new ArrayList<>(counts.values()));
        assertEquals(2, result.count(AccidentType.LEAVEROAD));
        assertTrue(result.hasAccident());
        assertFalse(new RunResult(7, 8, Outcome.TARGET_REACHED, List.of(), Map.of(), 60).hasAccident());
        assertEquals("CLASHWITHOTHERCAR#4", accidents.get(1).signature());
    }

    @Test
    void aRunResultCannotBeChangedThroughTheListsItWasGiven() {
        List<Accident> accidents = new ArrayList<>(List.of(new Accident(3, AccidentType.LEAVEROAD, 1, 2, -1)));
        RunResult result = new RunResult(7, 8, Outcome.TARGET_REACHED, accidents, Map.of(), 60);

        accidents.clear();

        assertEquals(1, result.accidents().size());
        assertThrows(UnsupportedOperationException.class, () -> result.accidents().clear());
    }

    // ---- fixtures ----

    /** A hand-placed moving vehicle, 5 m × 2 m, anchored at its front centre. */
    private record Other(double x, double y, double heading, double speed) implements Vehicle {
        @Override
        public int id() {
            return 1;
        }

        @Override
        public double length() {
            return 5;
        }

        @Override
        public double width() {
            return 2;
        }

        @Override
        public boolean isActive() {
            return true;
        }
    }

    /** The straight road with the car at its usual start, before any tick. */
    private static Scene straightScene() {
        return BuiltinRuns.scene(Situations.withoutTraffic(Situations.straight(List.of())), new SimState(1), FaultSwitchboard.none());
    }

    /** The straight road after 10 ticks: the car is under way in its lane, going east. */
    private static Scene movingScene() {
        SimState state = new SimState(1);
        Scene scene = BuiltinRuns.scene(Situations.withoutTraffic(Situations.straight(List.of())), state, FaultSwitchboard.none());
        for (int t = 0; t < 10; t++) {
            state.step();
        }
        AutonomousCar car = scene.autonomousCar();
        // preconditions of the blame tests: moving, heading (nearly) east, in its lane
        assertTrue(car.speed() > 0, "the car does not move");
        assertEquals(90, car.heading(), 10);
        assertEquals(48.5, car.y(), 0.3);
        assertEquals(Compass.EAST, car.selfReport().lane());
        return scene;
    }

    /** The straight road and its dead ends, with the given start, parked cars and Target (default x = 150, y = 48.5). */
    private static Layout straightFrom(StartPose start, List<ParkedCar> parked, Target target) {
        return Situations.layout(List.of(Situations.straightRoad()), Situations.straightRoadDeadEnds(), parked,
                target != null ? target : new Target(new Vec2(150, 48.5), 0), start);
    }

    /** The accidents of the first {@code ticks} ticks of a run of {@code layout}, without traffic. */
    private static List<Accident> firstTicks(Layout layout, int ticks) {
        SimState state = new SimState(1);
        Scene scene = BuiltinRuns.scene(Situations.withoutTraffic(layout), state, FaultSwitchboard.none());
        AccidentDetector detector = new AccidentDetector(scene.telemetry());
        state.schedule().scheduleRepeating(0, AccidentDetector.ORDERING, 1, detector);
        for (int t = 0; t < ticks; t++) {
            assertTrue(state.step());
        }
        assertEquals(ticks - 1, state.tick());
        return detector.accidents();
    }
}
