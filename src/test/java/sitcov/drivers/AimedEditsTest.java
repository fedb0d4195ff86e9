package sitcov.drivers;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Optional;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import sitcov.coverage.Criterion;
import sitcov.coverage.GridDefinition;
import sitcov.geom.Vec2;
import sitcov.world.Invariants;
import sitcov.world.Layout;
import sitcov.world.MapGenerator;
import sitcov.world.SituationEdit;
import sitcov.world.WorldMap;

class AimedEditsTest {
    private static final GridDefinition GRID = GridDefinition.paper();
    private static final int START_TARGET = 1;
    private static final int PREVIOUS_JUNCTION = 2;

    @Test
    void anAimAtStartTargetsLastBinPutsTheStartAndTheTargetTwoHundredMetresApart() {
        // one random map in about 800 000 has them 200 m apart; aimed edits of maps 1..30 do it often
        SplittableRandom choose = new SplittableRandom(7);
        int maps = 0;
        int apart = 0;
        for (long seed = 1; seed <= 30; seed++) {
            WorldMap map = MapGenerator.generate(seed);
            if (!map.layout().isRunnable() || distance(map) >= 200) {
                continue;
            }
            maps++;
            for (int i = 0; i < 10; i++) {
                SituationEdit edit = AimedEdits.toward(map, GRID, START_TARGET, 4, 1, choose);
                Optional<WorldMap> edited = edit.apply(map);
                if (edited.isPresent() && distance(edited.get()) >= 200) {
                    apart++;
                    assertEquals(List.of(), Invariants.violations(edited.get()), edit.text());
                    assertTrue(edited.get().layout().isRunnable(), edit.text());
                }
            }
        }
        assertTrue(maps >= 20, "most of maps 1..30 are runnable and under 200 m");
        assertTrue(apart >= maps, apart + " of " + maps * 10 + " aims landed 200 m or more apart (seed 7)");
    }

    @Test
    void anAimOneBinNearerThePreviousJunctionOftenLandsThereAndSometimesByANewBranchRoad() {
        SplittableRandom choose = new SplittableRandom(11);
        int aims = 0;
        int landed = 0;
        int byBranch = 0;
        for (long seed = 1; seed <= 40; seed++) {
            WorldMap map = MapGenerator.generate(seed);
            int bin = GRID.bins().get(PREVIOUS_JUNCTION).of(Criterion.PREVIOUS_JUNCTION_TO_TARGET.value(map.layout()));
            if (!map.layout().isRunnable() || bin <= 0) {
                continue;
            }
            for (int i = 0; i < 10; i++) {
                aims++;
                SituationEdit edit = AimedEdits.toward(map, GRID, PREVIOUS_JUNCTION, bin, -1, choose);
                Optional<WorldMap> edited = edit.apply(map);
                if (edited.isPresent() && GRID.bins().get(PREVIOUS_JUNCTION)
                        .of(Criterion.PREVIOUS_JUNCTION_TO_TARGET.value(edited.get().layout())) == bin - 1) {
                    landed++;
                    if (edit instanceof SituationEdit.AddBranchRoad) {
                        byBranch++;
                        assertEquals(map.layout().junctions().size() + 2, edited.get().layout().junctions().size(),
                                "a T-junction and a dead end added: " + edit.text());
                    }
                }
            }
        }
        assertTrue(aims >= 200, aims + " aims");
        assertTrue(landed * 5 >= aims, landed + " of " + aims + " aims landed one bin nearer (seed 11)");
        assertTrue(byBranch > 0, "no aim landed by a new branch road (seed 11)");
    }

    @Test
    void theSameRandomnessGivesTheSameEdits() {
        WorldMap map = MapGenerator.generate(3);
        for (int c = 0; c < 3; c++) {
            SplittableRandom a = new SplittableRandom(5);
            SplittableRandom b = new SplittableRandom(5);
            for (int i = 0; i < 20; i++) {
                assertEquals(AimedEdits.toward(map, GRID, c, 2, i % 2 == 0 ? 1 : -1, a),
                        AimedEdits.toward(map, GRID, c, 2, i % 2 == 0 ? 1 : -1, b));
                assertEquals(AimedEdits.random(map.layout(), a), AimedEdits.random(map.layout(), b));
            }
        }
    }

    @Test
    void aLongWalkOfTheSearchsEditsKeepsEveryTargetAndParkedCarOnTheRoadItNames() {
        // fault-search once wrote a situation whose Target stood on road 11 but named road 16, after a
        // move along road 16 carried it past the road's end; every edit, before the world's rules are
        // checked, must leave each element naming a road that holds it (or no road at all, which they refuse)
        SplittableRandom choose = new SplittableRandom(26);
        int edits = 0;
        int applied = 0;
        int renamed = 0;
        for (long seed = 1; seed <= 40; seed++) {
            WorldMap map = MapGenerator.generate(seed);
            if (!map.layout().isRunnable()) {
                continue;
            }
            for (int step = 0; step < 60; step++) {
                WorldMap parent = map;
                SituationEdit edit = choose.nextBoolean() ? AimedEdits.random(map.layout(), choose)
                        : AimedEdits.toward(map, GRID, choose.nextInt(3), 2, choose.nextBoolean() ? 1 : -1, choose);
                Optional<WorldMap> raw = edit.edit(map);
                edits++;
                if (raw.isEmpty()) {
                    continue;
                }
                Layout l = raw.get().layout();
                l.target().ifPresent(t -> assertTrue(holds(l, t.roadId(), t.position()), edit.text() + " on map " + parent.seed()));
                l.parkedCars().forEach(c -> assertTrue(holds(l, c.roadId(), c.centre()), edit.text() + " on map " + parent.seed()));
                if (edit instanceof SituationEdit.MoveTarget && l.target().get().roadId() != map.layout().target().get().roadId()) {
                    renamed++;
                }
                Optional<WorldMap> kept = edit.apply(map);
                if (kept.isPresent() && kept.get().layout().isRunnable()) {
                    assertEquals(List.of(), Invariants.violations(kept.get()), edit.text());
                    applied++;
                    map = kept.get();
                }
            }
        }
        assertTrue(edits >= 2000 && applied * 5 >= edits, applied + " of " + edits + " edits kept the rules (seed 26)");
        assertTrue(renamed > 0, "no move of the Target left its road for another (seed 26)");
    }

    /** Whether road {@code id} holds the point, or no road does (off the road is a rule of its own). */
    private static boolean holds(Layout layout, int id, Vec2 p) {
        return layout.roads().get(id).contains(p.x(), p.y())
                || layout.roads().stream().noneMatch(r -> r.contains(p.x(), p.y()));
    }

    private static double distance(WorldMap map) {
        Vec2 s = map.layout().carStart().orElseThrow().position();
        Vec2 t = map.layout().target().orElseThrow().position();
        return Math.hypot(s.x() - t.x(), s.y() - t.y());
    }
}
