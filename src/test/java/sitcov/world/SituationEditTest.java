package sitcov.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import sitcov.geom.Vec2;

class SituationEditTest {
    private static final WorldMap MAP = MapGenerator.generate(1);

    @Test
    void theTargetMovedAlongItsRoadKeepsItsSideAndTheWorldsRules() {
        Target before = MAP.layout().target().orElseThrow();
        Optional<WorldMap> edited = new SituationEdit.MoveTarget(3).apply(MAP);
        assertTrue(edited.isPresent(), "a 3 m move on a road of map 1 keeps the rules");
        Target after = edited.get().layout().target().orElseThrow();
        assertEquals(3, before.position().distanceTo(after.position().x(), after.position().y()), 1e-9);
        assertEquals(before.roadId(), after.roadId());
        assertEquals(List.of(), Invariants.violations(edited.get()));
        assertEquals(MAP.layout().parkedCars(), edited.get().layout().parkedCars(), "nothing else changed");
    }

    @Test
    void anEditThatBreaksARuleOfTheWorldGivesNoMap() {
        // 500 m along any road of a 200 m world is off the road
        assertEquals(Optional.empty(), new SituationEdit.MoveTarget(500).apply(MAP));
        assertEquals(Optional.empty(), new SituationEdit.MoveStart(-500).apply(MAP));
        // a parked car in the middle of a junction square
        Vec2 square = MAP.layout().junctions().get(0).centre();
        assertEquals(Optional.empty(), new SituationEdit.AddParkedCar(square.x(), square.y()).apply(MAP));
        assertEquals(Optional.empty(), new SituationEdit.RemoveParkedCar(9999).apply(MAP), "no such parked car");
    }

    @Test
    void aParkedCarRemovedOrAddedChangesOnlyTheParkedCars() {
        List<ParkedCar> cars = MAP.layout().parkedCars();
        int first = cars.get(0).id();
        WorldMap fewer = new SituationEdit.RemoveParkedCar(first).apply(MAP).orElseThrow();
        assertEquals(cars.size() - 1, fewer.layout().parkedCars().size());
        assertTrue(fewer.layout().parkedCars().stream().noneMatch(c -> c.centre().equals(cars.get(0).centre())));
        // put one back where the removed car stood: the rules held there before
        ParkedCar gone = cars.get(0);
        WorldMap back = new SituationEdit.AddParkedCar(gone.centre().x(), gone.centre().y()).apply(fewer).orElseThrow();
        ParkedCar added = back.layout().parkedCars().get(back.layout().parkedCars().size() - 1);
        assertEquals(gone.centre(), added.centre());
        assertEquals(fewer.layout().parkedCars().size(), added.id(), "the next free id, its index");
        assertEquals(MAP.layout().target(), back.layout().target());
    }

    @Test
    void aMapWithItsFirstParkedCarRemovedComesBackFromItsSituationFile() throws Exception {
        // situation files number parked cars from 0 in order: the cars after a removed one move up
        WorldMap fewer = new SituationEdit.RemoveParkedCar(MAP.layout().parkedCars().get(0).id()).apply(MAP).orElseThrow();
        assertEquals(fewer, readBack(fewer));
        assertEquals(MAP.layout().parkedCars().get(1).centre(), fewer.layout().parkedCars().get(0).centre());
        assertEquals(0, fewer.layout().parkedCars().get(0).id());
    }

    @Test
    void anEditedMapIsAValueASituationFileGivesBackWhole() throws Exception {
        WorldMap edited = new SituationEdit.MoveTarget(-2).apply(MAP).orElseThrow();
        WorldMap read = readBack(edited);
        assertEquals(edited, read);
        assertEquals("move-target:-2.00", new SituationEdit.MoveTarget(-2).text());
    }

    @Test
    void editsReachAStartTwoHundredMetresFromTheTargetThatNoRandomMapOfAMillionHad() {
        // the coverage question: is a start 200 m or more from the Target possible in a 200 x 100 m world?
        // Map 603's roads reach near opposite corners; sliding its start 40 m back and its Target 8 m on
        // along their roads puts them 201.5 m apart, every rule of the world kept
        WorldMap map = MapGenerator.generate(603);
        WorldMap edited = new SituationEdit.MoveStart(-40).apply(map)
                .flatMap(new SituationEdit.MoveTarget(8)::apply).orElseThrow();
        assertEquals(List.of(), Invariants.violations(edited));
        Vec2 start = edited.layout().carStart().orElseThrow().position();
        Vec2 target = edited.layout().target().orElseThrow().position();
        double dx = start.x() - target.x();
        double dy = start.y() - target.y();
        assertTrue(Math.sqrt(dx * dx + dy * dy) >= 200, "start " + start + ", Target " + target);
        Vec2 before = map.layout().carStart().orElseThrow().position();
        assertTrue(before.distanceTo(map.layout().target().orElseThrow().position()) < 200, "the unedited map is not");
    }

    @Test
    void theTargetPlacedOnAnotherRoadKeepsTheRulesAndComesBackFromItsSituationFile() throws Exception {
        Target before = MAP.layout().target().orElseThrow();
        int placed = 0;
        for (Road road : MAP.layout().roads()) {
            if (road.id() == before.roadId()) {
                continue;
            }
            // the middle of the road, in one of its lanes
            Vec2 middle = road.point((road.from() + road.to()) / 2, road.centre() + 1.5);
            var edited = new SituationEdit.PlaceTarget(middle.x(), middle.y()).apply(MAP);
            if (edited.isEmpty()) {
                continue; // a junction or a parked car there: the rules refuse it
            }
            placed++;
            Target after = edited.get().layout().target().orElseThrow();
            assertEquals(road.id(), after.roadId(), "the Target is on the road it was put on");
            assertEquals(0, after.position().distanceTo(middle.x(), middle.y()), 0.001);
            assertEquals(List.of(), Invariants.violations(edited.get()));
            assertEquals(MAP.layout().carStart(), edited.get().layout().carStart(), "nothing else changed");
            assertEquals(edited.get(), readBack(edited.get()));
        }
        assertTrue(placed > 0, "map 1 has another road with a free middle");
        assertEquals(Optional.empty(), new SituationEdit.PlaceTarget(-50, -50).apply(MAP), "off every road");
    }

    @Test
    void trafficReseededFromTheMapsOwnSeedIsItsOwnAndFromAnotherIsOther() {
        WorldMap own = new SituationEdit.ReseedTraffic(MAP.seed()).apply(MAP).orElseThrow();
        assertEquals(MAP, own, "the generator places a map's traffic from its own seed");
        WorldMap other = new SituationEdit.ReseedTraffic(MAP.seed() + 1).apply(MAP).orElseThrow();
        assertTrue(!other.movingCars().equals(MAP.movingCars()), "another seed, other traffic");
        assertEquals(MAP.layout(), other.layout(), "the same roads, parked cars, Target and start");
        assertEquals(List.of(), Invariants.violations(other));
        assertEquals("reseed-traffic:2", new SituationEdit.ReseedTraffic(2).text());
    }

    @Test
    void theStartPlacedOnAnotherRoadStandsOnALaneCentreFacingThatLanesWay() throws Exception {
        int placed = 0;
        for (Road road : MAP.layout().roads()) {
            // the middle of the road, off its lane centres: the start is put on the nearer lane's centre
            Vec2 middle = road.point((road.from() + road.to()) / 2, road.centre() - 0.4);
            var edited = new SituationEdit.PlaceStart(middle.x(), middle.y()).apply(MAP);
            if (edited.isEmpty()) {
                continue; // a junction, a parked car or a moving car there: the rules refuse it
            }
            placed++;
            StartPose after = edited.get().layout().carStart().orElseThrow();
            // centre − 0.4 is in the first half: northbound or eastbound, its lane centre 1.5 m off the centre line
            sitcov.geom.Compass way = road.isNorthSouth() ? sitcov.geom.Compass.NORTH : sitcov.geom.Compass.EAST;
            assertEquals(way, after.heading());
            assertEquals(road.centre() - 1.5, road.across(after.position().x(), after.position().y()), 1e-9);
            assertEquals(road.along(middle.x(), middle.y()), road.along(after.position().x(), after.position().y()), 0.001);
            assertEquals(List.of(), Invariants.violations(edited.get()));
            assertEquals(MAP.layout().target(), edited.get().layout().target(), "nothing else changed");
            assertEquals(edited.get(), readBack(edited.get()));
        }
        assertTrue(placed > 1, "map 1 has roads with a free middle");
        assertEquals(Optional.empty(), new SituationEdit.PlaceStart(-50, -50).apply(MAP), "off every road");
    }

    @Test
    void aChainOfEditsKeepsTheRulesOnlyAtItsEnd() {
        // a branch road, then the start placed on the new branch: the chain gives what the two give in turn
        SituationEdit branch = firstBranchThatFits(MAP);
        WorldMap grown = branch.apply(MAP).orElseThrow();
        Road added = grown.layout().roads().get(MAP.layout().roads().size());
        Vec2 onBranch = added.point((added.from() + added.to()) / 2, added.centre() + 1.5);
        SituationEdit start = new SituationEdit.PlaceStart(onBranch.x(), onBranch.y());
        SituationEdit chain = new SituationEdit.Chain(List.of(branch, start));
        Optional<WorldMap> both = chain.apply(MAP);
        assertTrue(both.isPresent(), "the middle of a new branch is free for the start");
        assertEquals(start.apply(grown), both);
        assertEquals(Optional.empty(), start.apply(MAP), "without the branch there is no road there");
        assertEquals(branch.text() + "+" + start.text(), chain.text());
        // the Target moved 500 m (off every road) and back: each step alone breaks the rules, the chain keeps them
        SituationEdit there = new SituationEdit.MoveTarget(500);
        assertEquals(Optional.empty(), there.apply(MAP));
        assertEquals(Optional.of(MAP.layout().target()), new SituationEdit.Chain(List.of(there, new SituationEdit.MoveTarget(-500)))
                .apply(MAP).map(m -> m.layout().target()));
    }

    @Test
    void aParkedCarWithinSixMetresOfATargetTwoHundredMetresFromTheStartIsPossible() throws Exception {
        // the same question for the cells nothing reached: one of them, C1 1.01-6.01 m in start-target's
        // last bin. A situation coverage-search built (start near the north-east corner, Target near the west
        // edge) and a parked car added at the kerb 5 m behind the Target: every rule kept, the car runnable
        WorldMap far = SituationFile.read(java.nio.file.Path.of("src", "test", "resources", "situations",
                "start-200m-from-target.situation"));
        WorldMap edited = new SituationEdit.AddParkedCar(6.0, 73.81).apply(far).orElseThrow();
        assertEquals(List.of(), Invariants.violations(edited));
        assertTrue(edited.layout().isRunnable());
        Vec2 start = edited.layout().carStart().orElseThrow().position();
        Vec2 target = edited.layout().target().orElseThrow().position();
        assertTrue(Math.hypot(start.x() - target.x(), start.y() - target.y()) >= 200, start + " to " + target);
        double nearest = edited.layout().parkedCars().stream()
                .mapToDouble(c -> Math.hypot(c.centre().x() - target.x(), c.centre().y() - target.y())).min().orElseThrow();
        assertTrue(nearest > 1.01 && nearest < 6.01, "nearest parked car " + nearest + " m from the Target");
        double before = far.layout().parkedCars().stream()
                .mapToDouble(c -> Math.hypot(c.centre().x() - target.x(), c.centre().y() - target.y())).min().orElseThrow();
        assertTrue(before > 6.01, "the search's own situation had none that near");
    }

    @Test
    void editsKeepTheGeneratorsRoomAroundTheTarget() {
        // the generator keeps the Target 1 m clear of parked cars (nearer, the car could not come within
        // capture distance) and the start 3 m from it; an edit that breaks either gives no map
        Target target = MAP.layout().target().orElseThrow();
        Road road = MAP.layout().roads().get(target.roadId());
        Vec2 t = target.position();
        // a parked car whose kerb-side body ends 0.5 m short of the Target, along its road
        double along = road.along(t.x(), t.y()) + (Dimensions.CAR_LENGTH / 2 + 0.5);
        Vec2 car = road.point(along, road.across(t.x(), t.y()));
        SituationEdit tooNear = new SituationEdit.AddParkedCar(car.x(), car.y());
        List<String> broken = Invariants.violations(tooNear.edit(MAP).orElseThrow());
        assertTrue(broken.stream().anyMatch(v -> v.contains("within 1.0 m of a parked car")), broken.toString());
        assertEquals(Optional.empty(), tooNear.apply(MAP));
        Vec2 beside = road.point(road.along(t.x(), t.y()) + 2, road.across(t.x(), t.y()));
        SituationEdit startBeside = new SituationEdit.PlaceStart(beside.x(), beside.y());
        WorldMap placed = startBeside.edit(MAP).orElseThrow();
        assertTrue(placed.layout().carStart().orElseThrow().position().distanceTo(t) < 3, "the start 2 m along, on a lane centre");
        assertTrue(Invariants.violations(placed).stream().anyMatch(v -> v.contains("within 3.0 m of the Target")),
                Invariants.violations(placed).toString());
    }

    @Test
    void aParkedCarAddedAcrossTheRoadFromAnotherAndBarelyStaggeredIsRefusedAsItWouldBlockTheRoad() {
        // the generator spaces cars on opposite kerbs (5 + 2) x 1.5 = 10.5 m apart along the road, so a car
        // can always pass between; 3 m apart they leave no way through
        ParkedCar parked = MAP.layout().parkedCars().get(0);
        Road road = MAP.layout().roads().get(parked.roadId());
        double along = road.along(parked.centre().x(), parked.centre().y());
        double otherKerb = 2 * road.centre() - road.across(parked.centre().x(), parked.centre().y());
        Vec2 staggered = road.point(along + 3, otherKerb);
        SituationEdit blocking = new SituationEdit.AddParkedCar(staggered.x(), staggered.y());
        WorldMap blocked = blocking.edit(MAP).orElseThrow();
        ParkedCar added = blocked.layout().parkedCars().get(blocked.layout().parkedCars().size() - 1);
        assertEquals(otherKerb, road.across(added.centre().x(), added.centre().y()), 0.5, "at the other kerb");
        List<String> broken = Invariants.violations(blocked);
        assertTrue(broken.stream().anyMatch(v -> v.contains("nearer along their road than the generator spaces them")),
                broken.toString());
        assertEquals(Optional.empty(), blocking.apply(MAP));
    }

    @Test
    void theStartPlacedJustAheadOfAMovingCarBreaksTheGeneratorsFiveMetres() {
        StartPose moving = MAP.movingCars().get(0);
        Vec2 ahead = moving.position().moved(moving.heading().bearing(), 4);
        WorldMap placed = new SituationEdit.PlaceStart(ahead.x(), ahead.y()).edit(MAP).orElseThrow();
        assertEquals(4, placed.layout().carStart().orElseThrow().position().distanceTo(moving.position()), 0.01);
        List<String> broken = Invariants.violations(placed);
        assertTrue(broken.stream().anyMatch(v -> v.equals("moving car 0 starts within 5.0 m of the autonomous car")),
                broken.toString());
    }

    /** The first branch road, 30 m either way from a point 5 m apart along the roads of {@code map}, that keeps the rules. */
    private static SituationEdit firstBranchThatFits(WorldMap map) {
        for (Road road : map.layout().roads()) {
            for (double along = road.from() + 10; along < road.to() - 10; along += 5) {
                for (double length : new double[] {-30, 30}) {
                    SituationEdit branch = new SituationEdit.AddBranchRoad(road.id(), along, length);
                    if (branch.apply(map).isPresent()) {
                        return branch;
                    }
                }
            }
        }
        throw new AssertionError("no branch road fits map " + map.seed());
    }

    /** The map as its situation file gives it back. */
    private static WorldMap readBack(WorldMap map) throws SituationFormatException {
        return SituationFile.parse(List.of(SituationFile.format(map).split("\n")), "edited");
    }
    @Test
    void aTargetOrParkedCarSlidPastItsRoadsEndOntoAnotherRoadNamesTheRoadItLandsOn() {
        // a slide past a road's end, across a gap or a crossing road, can land on another road;
        // the moved element kept its old road's id, which the car's route and the spacing rule then trusted
        int targets = 0;
        int cars = 0;
        for (long seed = 1; seed <= 60; seed++) {
            WorldMap map = MapGenerator.generate(seed);
            Layout l = map.layout();
            RoadNetwork network = RoadNetwork.of(l);
            for (double by = -60; by <= 60; by += 0.5) {
                if (l.target().isPresent()) {
                    Target t = l.target().get();
                    Road landed = anotherRoadAfterSlide(network, l.roads().get(t.roadId()), t.position(), by);
                    if (landed != null) {
                        targets++;
                        Target moved = new SituationEdit.MoveTarget(by).edit(map).orElseThrow().layout().target().orElseThrow();
                        assertTrue(landed.contains(moved.position().x(), moved.position().y()), "seed " + seed + " by " + by);
                        assertEquals(landed.id(), moved.roadId(), "seed " + seed + " by " + by);
                    }
                }
                for (ParkedCar c : l.parkedCars()) {
                    Road landed = anotherRoadAfterSlide(network, l.roads().get(c.roadId()), c.centre(), by);
                    if (landed != null) {
                        cars++;
                        ParkedCar moved = new SituationEdit.MoveParkedCar(c.id(), by).edit(map).orElseThrow()
                                .layout().parkedCars().get(c.id());
                        assertEquals(landed.id(), moved.roadId(), "seed " + seed + " car " + c.id() + " by " + by);
                    }
                }
            }
        }
        assertTrue(targets > 0 && cars > 0, targets + " Target and " + cars + " parked-car slides leave their road for another");
    }

    /** The road {@code p} slid {@code by} along {@code road} lands on, out of junctions, if it left {@code road}; or null. */
    private static Road anotherRoadAfterSlide(RoadNetwork network, Road road, Vec2 p, double by) {
        Vec2 q = road.point(road.along(p.x(), p.y()) + by, road.across(p.x(), p.y()));
        return road.contains(q.x(), q.y()) || network.isInJunction(q.x(), q.y()) ? null : network.roadAt(q.x(), q.y());
    }
}
