package sitcov.oracle;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.EnumSet;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;
import sitcov.builtin.BuiltinRuns;
import sitcov.control.Vehicle;
import sitcov.faults.Fault;
import sitcov.geom.Box;
import sitcov.geom.BoxGap;
import sitcov.judge.RunRecord;
import sitcov.judge.Simulator;
import sitcov.vehicles.Dynamics;
import sitcov.vehicles.Telemetry;
import sitcov.world.Junction;
import sitcov.world.MapGenerator;
import sitcov.world.Situations;
import sitcov.world.WorldMap;

/**
 * The near-miss watcher on real runs. The reference car has accidents of its own on a few random
 * maps (faults/README.md, "How close to failure: near misses and robustness"): on maps 1..400, with the internal
 * seed equal to the map's, map 86
 * times out, 147 hits a moving car, 212 crosses the centre line, 325 leaves the road, 387 touches a
 * parked car, and on 302 a moving car on the centre line touches it (an excused contact).
 */
class NearMissesTest {
    private static final double EPS = 1e-9;

    private record Watched(RunRecord record, NearMisses nearMisses, Reference reference) {
        EnumSet<AccidentType> accidentTypes() {
            EnumSet<AccidentType> types = EnumSet.noneOf(AccidentType.class);
            record.result().accidents().forEach(a -> types.add(a.type()));
            return types;
        }
    }

    private static Watched watch(WorldMap map, long seed, Set<Fault> faults) {
        NearMisses[] watcher = new NearMisses[1];
        Reference reference = new Reference();
        RunRecord record = BuiltinRuns.run(map, seed, faults, (tick, run, detector) -> {
            if (watcher[0] == null) {
                watcher[0] = new NearMisses(run);
            }
            watcher[0].afterTick(run);
            reference.look(run);
        });
        return new Watched(record, watcher[0], reference);
    }

    private static Watched watch(long mapSeed) {
        return watch(MapGenerator.generate(mapSeed), mapSeed, Set.of());
    }

    @Test
    void everyAccidentARunHadHasARobustnessBelowZeroAndEveryOtherTypeOneAboveIt() {
        EnumSet<AccidentType> seen = EnumSet.noneOf(AccidentType.class);
        int clean = 0;
        for (long map : new long[] {1, 2, 3, 4, 5, 86, 147, 212, 289, 325, 387}) {
            Watched w = watch(map);
            EnumSet<AccidentType> had = w.accidentTypes();
            seen.addAll(had);
            clean += had.isEmpty() ? 1 : 0;
            for (AccidentType type : AccidentType.values()) {
                double rho = w.nearMisses().robustness(type);
                if (!had.contains(type)) {
                    assertTrue(rho > 0, "map " + map + ": no " + type + ", yet ρ = " + rho);
                } else if (type == AccidentType.TIMEOUT) {
                    assertEquals(0, rho, "map " + map + " timed out");
                } else {
                    assertTrue(rho < 0, "map " + map + ": " + type + " happened, yet ρ = " + rho);
                }
            }
        }
        assertEquals(EnumSet.allOf(AccidentType.class), seen, "the runs hold every type of accident");
        assertTrue(clean >= 3, "and runs with none: " + clean);
    }

    @Test
    void theSameHoldsForAFaultyCarsAccidents() {
        // stale waypoints (fault 2) on map 10: it hits a parked car, among others
        Watched w = watch(MapGenerator.generate(10), 10, Set.of(Fault.ofId(2)));

        assertTrue(w.accidentTypes().contains(AccidentType.CLASHWITHOBSTACLE));
        for (AccidentType type : AccidentType.values()) {
            double rho = w.nearMisses().robustness(type);
            assertEquals(w.accidentTypes().contains(type), rho <= 0, type + ": ρ = " + rho);
        }
    }

    @Test
    void aContactTheOtherCarIsBlamedForIsANearMissButNotAFailure() {
        Watched w = watch(302);

        assertEquals(Set.of(Blame.EXCUSED_OTHER_ON_CENTRE_LINE), w.record().result().excusedContacts().keySet());
        assertFalse(w.accidentTypes().contains(AccidentType.CLASHWITHOTHERCAR));
        assertTrue(w.nearMisses().least(NearMiss.MOVING_GAP) < 0, "the footprints overlapped");
        assertTrue(w.nearMisses().robustness(AccidentType.CLASHWITHOTHERCAR) > 0);
    }

    @Test
    void theGapsAreTheLeastDistancesBetweenTheFootprintsOverTheRun() {
        for (long map : new long[] {147, 387}) {
            Watched w = watch(map);
            NearMisses n = w.nearMisses();
            assertEquals(w.reference().parkedGap, n.least(NearMiss.PARKED_GAP), EPS, "map " + map);
            assertEquals(w.reference().movingGap, n.least(NearMiss.MOVING_GAP), EPS, "map " + map);
            assertTrue(Double.isFinite(w.reference().parkedGap) && Double.isFinite(w.reference().movingGap));
        }
    }

    @Test
    void thePostEncroachmentTimeIsTheLeastWaitBetweenOneLeavingASquareAndTheOtherEntering() {
        int met = 0;
        for (long map : new long[] {86, 147, 212, 289}) {
            Watched w = watch(map);
            assertEquals(w.reference().pet, w.nearMisses().least(NearMiss.POST_ENCROACHMENT), "map " + map);
            met += Double.isFinite(w.reference().pet) ? 1 : 0;
        }
        assertTrue(met >= 2, "the car met traffic at a junction on some of these maps: " + met);
    }

    @Test
    void onTheEmptyStraightRoadTheCarKeepsHalfAMetreFromTheKerbAndTheCentreLine() {
        // the 2 m car in the middle of the 3 m lane: 0.5 m either side; nothing else to come near
        Watched w = watch(Situations.withoutTraffic(Situations.straight(List.of())), 1, Set.of());
        NearMisses n = w.nearMisses();

        assertEquals(0.5, n.least(NearMiss.ROAD_EDGE), 0.05);
        assertEquals(0.5, n.least(NearMiss.CENTRE_LINE), 0.05);
        for (NearMiss none : List.of(NearMiss.MOVING_GAP, NearMiss.PARKED_GAP, NearMiss.TIME_TO_COLLISION,
                NearMiss.POST_ENCROACHMENT)) {
            assertEquals(Double.POSITIVE_INFINITY, n.least(none), none.name());
            assertEquals(-1, n.tickOf(none));
        }
        // reached at the run's last tick, ticks − 1
        long reachedAt = w.record().result().ticks() - 1;
        assertEquals(Outcome.TARGET_REACHED, w.record().result().outcome());
        assertEquals(Dynamics.TIMEOUT_TICKS - reachedAt, n.robustness(AccidentType.TIMEOUT));
    }

    @Test
    void passingAParkedCarOverTheCentreLineIsExcusedAndKeepsTheRobustnessPositive() {
        Watched w = watch(Situations.withoutTraffic(Situations.straight(List.of(Situations.parkedInEastboundLane(0, 90)))),
                1, Set.of());

        assertTrue(w.reference().wasOverCentreLine, "the car pulled out over the line");
        assertEquals(List.of(), w.record().result().accidents());
        assertTrue(w.nearMisses().robustness(AccidentType.CROSSCENTRELINE) > 0);
        assertTrue(w.nearMisses().least(NearMiss.PARKED_GAP) > 0 && w.nearMisses().least(NearMiss.PARKED_GAP) < 3);
    }

    @Test
    void theSameRunGivesTheSameMeasures() {
        Watched once = watch(147);
        Watched again = watch(147);

        assertEquals(once.nearMisses().measures(), again.nearMisses().measures());
        for (NearMiss m : NearMiss.values()) {
            assertEquals(once.nearMisses().tickOf(m), again.nearMisses().tickOf(m));
        }
    }

    /**
     * The same quantities worked out plainly, from {@link Box} footprints and the oracle's own tests:
     * the gaps with no short cuts, PET from {@link Box#overlaps(sitcov.geom.Rect)} on T-junction squares.
     */
    private static final class Reference {
        double parkedGap = Double.POSITIVE_INFINITY;
        double movingGap = Double.POSITIVE_INFINITY;
        double pet = Double.POSITIVE_INFINITY;
        boolean wasOverCentreLine;
        private boolean[] carIn;
        private long[] carLeft;
        private boolean[][] otherIn;
        private long[][] otherLeft;
        private List<Junction> tees;
        private CentreLine centreLine;

        void look(Telemetry run) {
            if (tees == null) {
                tees = run.network().junctions().stream().filter(j -> !j.isDeadEnd()).toList();
                carIn = new boolean[tees.size()];
                carLeft = new long[tees.size()];
                java.util.Arrays.fill(carLeft, -1);
                otherIn = new boolean[run.movingCars().size()][tees.size()];
                otherLeft = new long[run.movingCars().size()][tees.size()];
                for (long[] row : otherLeft) {
                    java.util.Arrays.fill(row, -1);
                }
                centreLine = new CentreLine(run.network());
            }
            long tick = run.tick();
            Box car = run.car().footprint();
            wasOverCentreLine |= centreLine.isOver(car);
            for (Box parked : run.parkedBodies()) {
                parkedGap = Math.min(parkedGap, BoxGap.signedDistance(car, parked));
            }
            List<? extends Vehicle> moving = run.movingCars();
            for (Vehicle other : moving) {
                if (other.isActive()) {
                    movingGap = Math.min(movingGap, BoxGap.signedDistance(car, other.footprint()));
                }
            }
            for (int j = 0; j < tees.size(); j++) {
                boolean carNow = car.overlaps(tees.get(j).square());
                boolean carEnters = carNow && !carIn[j];
                if (carIn[j] && !carNow) {
                    carLeft[j] = tick;
                }
                carIn[j] = carNow;
                for (int i = 0; i < moving.size(); i++) {
                    Vehicle other = moving.get(i);
                    boolean otherNow = other.isActive() && other.footprint().overlaps(tees.get(j).square());
                    boolean otherEnters = otherNow && !otherIn[i][j];
                    if (otherIn[i][j] && !otherNow) {
                        otherLeft[i][j] = tick;
                    }
                    otherIn[i][j] = otherNow;
                    if (carEnters && !otherNow && otherLeft[i][j] >= 0) {
                        pet = Math.min(pet, tick - otherLeft[i][j]);
                    }
                    if (otherEnters && !carNow && carLeft[j] >= 0) {
                        pet = Math.min(pet, tick - carLeft[j]);
                    }
                }
            }
        }
    }
}
