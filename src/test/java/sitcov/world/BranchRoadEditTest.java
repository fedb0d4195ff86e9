package sitcov.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import sitcov.coverage.Criterion;
import sitcov.geom.Compass;
import sitcov.geom.Vec2;

class BranchRoadEditTest {
    private static final WorldMap MAP = MapGenerator.generate(1);

    /** The first branch that applies to {@code map}, trying every road, every 5 m, 30 m either way. */
    private static SituationEdit.AddBranchRoad firstBranchThatFits(WorldMap map) {
        for (Road road : map.layout().roads()) {
            for (double along = road.from() + 10; along < road.to() - 10; along += 5) {
                for (double length : new double[] {30, -30}) {
                    var edit = new SituationEdit.AddBranchRoad(road.id(), along, length);
                    if (edit.apply(map).isPresent()) {
                        return edit;
                    }
                }
            }
        }
        throw new AssertionError("no branch fits on map " + map.seed());
    }

    @Test
    void anAddedBranchLeavesItsParentAtANewTJunctionAndEndsInADeadEnd() throws Exception {
        var edit = firstBranchThatFits(MAP);
        WorldMap grown = edit.apply(MAP).orElseThrow();
        Layout before = MAP.layout();
        Layout after = grown.layout();
        assertEquals(before.roads().size() + 1, after.roads().size());
        Road branch = after.roads().get(after.roads().size() - 1);
        Road parent = after.roads().get(edit.parent());
        assertEquals(parent.axis().other(), branch.axis(), "a branch crosses its parent's axis");
        boolean reachesTheEdge = branch.from() == 0 || branch.to() == (branch.isNorthSouth() ? 100 : 200);
        assertTrue(branch.length() == 30 || reachesTheEdge && branch.length() >= 23 && branch.length() < 30,
                "30 m, or as far as the world's edge: " + branch);
        assertEquals(before.tJunctionCount() + 1, after.tJunctionCount());
        assertEquals(before.deadEndCount() + 1, after.deadEndCount());
        Junction t = after.junctions().get(after.junctions().size() - 2);
        assertEquals(3, t.arms().size(), "the new T-junction has three arms");
        assertEquals(parent.point(edit.along(), parent.centre()), t.centre(), "on the parent's centre line, where asked");
        assertTrue(branch.carries(after.junctions().get(after.junctions().size() - 1).centre()), "the dead end closes the branch");
        assertEquals(List.of(), Invariants.violations(grown));
        assertEquals(before.parkedCars(), after.parkedCars());
        assertEquals(before.target(), after.target());
        assertEquals(grown, SituationFile.parse(List.of(SituationFile.format(grown).split("\n")), "grown"));
    }

    @Test
    void removingTheBranchJustAddedGivesBackTheMapExactly() {
        var edit = firstBranchThatFits(MAP);
        WorldMap grown = edit.apply(MAP).orElseThrow();
        int added = grown.layout().roads().size() - 1;
        assertEquals(Optional.of(MAP), new SituationEdit.RemoveBranchRoad(added).apply(grown));
        assertEquals("remove-branch-road:" + added, new SituationEdit.RemoveBranchRoad(added).text());
    }

    @Test
    void aBranchThatWouldMeetAnotherRoadOrCrowdItsParentsEndIsRefused() {
        Road first = MAP.layout().roads().get(0);
        // 5 m from the parent's end: a junction must be 9 m in
        assertEquals(Optional.empty(), new SituationEdit.AddBranchRoad(0, first.from() + 5, 30).apply(MAP));
        // shorter than a road may be
        assertEquals(Optional.empty(), new SituationEdit.AddBranchRoad(0, (first.from() + first.to()) / 2, 10).apply(MAP));
        // across the whole world where a 25 m branch fits: some such long branches meet another road
        int refusedWhereAShortOneFits = 0;
        for (long seed = 1; seed <= 10; seed++) {
            WorldMap map = MapGenerator.generate(seed);
            for (Road road : map.layout().roads()) {
                for (double along = road.from() + 9; along <= road.to() - 9; along += 3) {
                    for (double sign : new double[] {1, -1}) {
                        boolean shortFits = new SituationEdit.AddBranchRoad(road.id(), along, sign * 25).apply(map).isPresent();
                        Optional<WorldMap> far = new SituationEdit.AddBranchRoad(road.id(), along, sign * 300).apply(map);
                        far.ifPresent(m -> assertEquals(List.of(), Invariants.violations(m)));
                        if (shortFits && far.isEmpty()) {
                            refusedWhereAShortOneFits++;
                        }
                    }
                }
            }
        }
        assertTrue(refusedWhereAShortOneFits > 0, "roads of maps 1..10 block some long branches");
        assertEquals(Optional.empty(), new SituationEdit.AddBranchRoad(99, 50, 30).apply(MAP), "no such road");
    }

    @Test
    void onlyALeafBranchHoldingNeitherTargetNorStartCanBeRemoved() {
        Layout l = MAP.layout();
        assertEquals(Optional.empty(), new SituationEdit.RemoveBranchRoad(0).apply(MAP), "the first road is no branch");
        assertEquals(Optional.empty(), new SituationEdit.RemoveBranchRoad(l.target().orElseThrow().roadId()).apply(MAP));
        int removed = 0;
        for (Road road : l.roads()) {
            Optional<WorldMap> pruned = new SituationEdit.RemoveBranchRoad(road.id()).apply(MAP);
            boolean hasBranch = l.junctions().stream().anyMatch(j -> !j.isDeadEnd() && road.carries(j.centre())
                    && !j.centre().equals(road.start()) && !j.centre().equals(road.end()));
            if (hasBranch) {
                assertEquals(Optional.empty(), pruned, "road " + road.id() + " has a branch of its own");
            }
            if (pruned.isPresent()) {
                removed++;
                Layout p = pruned.get().layout();
                assertEquals(l.roads().size() - 1, p.roads().size());
                assertEquals(l.junctions().size() - 2, p.junctions().size());
                assertEquals(List.of(), Invariants.violations(pruned.get()));
                long parkedThere = l.parkedCars().stream().filter(c -> c.roadId() == road.id()).count();
                assertEquals(l.parkedCars().size() - parkedThere, p.parkedCars().size(), "its parked cars went with it");
                // the Target still stands on a road of the same place
                Vec2 t = p.target().orElseThrow().position();
                assertTrue(p.roads().get(p.target().orElseThrow().roadId()).contains(t.x(), t.y()));
            }
        }
        assertTrue(removed > 0, "map 1 has a leaf branch to remove");
    }

    @Test
    void movingCarsThatStoodOnARemovedRoadAreRecordedAsOmissions() throws Exception {
        for (long seed = 1; seed <= 200; seed++) {
            WorldMap map = MapGenerator.generate(seed);
            for (Road road : map.layout().roads()) {
                long standing = map.movingCars().stream()
                        .filter(s -> road.contains(s.position().x(), s.position().y())).count();
                Optional<WorldMap> pruned = new SituationEdit.RemoveBranchRoad(road.id()).apply(map);
                if (standing > 0 && pruned.isPresent()) {
                    assertEquals(map.movingCars().size() - standing, pruned.get().movingCars().size());
                    assertEquals(map.movingCarOmissions().size() + standing, pruned.get().movingCarOmissions().size());
                    assertTrue(pruned.get().movingCarOmissions().get(pruned.get().movingCarOmissions().size() - 1)
                            .reason().contains("remove-branch-road:" + road.id()));
                    assertEquals(pruned.get(), SituationFile.parse(
                            List.of(SituationFile.format(pruned.get()).split("\n")), "pruned"));
                    return;
                }
            }
        }
        throw new AssertionError("no map of 1..200 has a removable branch with moving cars on it");
    }

    @Test
    void aBranchJustBehindTheTargetMakesItsPreviousJunctionNear() {
        // the search's use: a T-junction 8 m behind the Target in its lane puts C3 under 10 m
        for (long seed = 1; seed <= 100; seed++) {
            WorldMap map = MapGenerator.generate(seed);
            Target target = map.layout().target().orElseThrow();
            Road road = map.layout().roads().get(target.roadId());
            Compass lane = road.laneDirectionAt(target.position().x(), target.position().y());
            double behind = road.along(target.position().x(), target.position().y())
                    - 8 * (lane == Compass.SOUTH || lane == Compass.EAST ? 1 : -1);
            for (double length : new double[] {25, -25}) {
                Optional<WorldMap> grown = new SituationEdit.AddBranchRoad(road.id(), behind, length).apply(map);
                if (grown.isPresent()) {
                    // from the junction's centre on the centre line to the Target in its lane
                    double expected = Math.hypot(8, road.across(target.position().x(), target.position().y()) - road.centre());
                    assertTrue(Criterion.PREVIOUS_JUNCTION_TO_TARGET.value(map.layout()) > expected + 0.01, "seed " + seed);
                    assertEquals(expected, Criterion.PREVIOUS_JUNCTION_TO_TARGET.value(grown.get().layout()), 1e-9,
                            "seed " + seed);
                    assertTrue(expected < 10, "the first bin of C3");
                    return;
                }
            }
        }
        throw new AssertionError("no map of 1..100 takes a branch 8 m behind its Target");
    }
}
