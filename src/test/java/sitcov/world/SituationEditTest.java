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
        assertTrue(fewer.layout().parkedCars().stream().noneMatch(c -> c.id() == first));
        // put one back where the removed car stood: the rules held there before
        ParkedCar gone = cars.get(0);
        WorldMap back = new SituationEdit.AddParkedCar(gone.centre().x(), gone.centre().y()).apply(fewer).orElseThrow();
        ParkedCar added = back.layout().parkedCars().get(back.layout().parkedCars().size() - 1);
        assertEquals(gone.centre(), added.centre());
        assertEquals(cars.stream().mapToInt(ParkedCar::id).max().orElseThrow() + 1, added.id(), "the next free id");
        assertEquals(MAP.layout().target(), back.layout().target());
    }

    @Test
    void anEditedMapIsAValueASituationFileGivesBackWhole() throws Exception {
        WorldMap edited = new SituationEdit.MoveTarget(-2).apply(MAP).orElseThrow();
        WorldMap read = SituationFile.parse(List.of(SituationFile.format(edited).split("\n")), "edited");
        assertEquals(edited, read);
        assertEquals("move-target:-2.00", new SituationEdit.MoveTarget(-2).text());
    }

    @Test
    void editsReachAStartTwoHundredMetresFromTheTargetThatNoRandomMapOfAMillionHad() {
        // issue 16's question: is a start 200 m or more from the Target possible in a 200 x 100 m world?
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
}
