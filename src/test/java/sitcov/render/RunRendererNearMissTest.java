package sitcov.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;
import sitcov.builtin.BuiltinRuns;
import sitcov.judge.Simulator;
import sitcov.oracle.AccidentType;
import sitcov.oracle.NearMiss;
import sitcov.oracle.NearMisses;
import sitcov.oracle.RunResult;
import sitcov.world.MapGenerator;
import sitcov.world.WorldMap;

/** The closest approaches a run picture marks, and the least ρ its caption gives. */
class RunRendererNearMissTest {
    private static final int SCALE = MapRenderer.DEFAULT_SCALE;

    private record Drawn(WorldMap map, TrajectoryRecorder trajectory, RunResult result) {
        static Drawn of(long seed) {
            WorldMap map = MapGenerator.generate(seed);
            TrajectoryRecorder trajectory = new TrajectoryRecorder();
            RunResult result = BuiltinRuns.run(map, seed, Set.of(), trajectory).result();
            return new Drawn(map, trajectory, result);
        }

        NearMisses watched() {
            return trajectory.nearMisses().orElseThrow();
        }
    }

    /** Map 1: no accident, a parked car passed about half a metre off (see TraceWriterTest). */
    @Test
    void eachClosestApproachIsMarkedAtTheCarsFootprintOnTheTickItsLeastWasReached() {
        Drawn run = Drawn.of(1);
        assertTrue(run.result().accidents().isEmpty());
        List<RunRenderer.Closest> closest = RunRenderer.closest(run.trajectory(), run.result());
        assertEquals(List.of(NearMiss.MOVING_GAP, NearMiss.PARKED_GAP, NearMiss.ROAD_EDGE, NearMiss.CENTRE_LINE),
                closest.stream().map(RunRenderer.Closest::measure).toList());
        BufferedImage picture = new RunRenderer(SCALE).render(run.map(), run.trajectory(), run.result());
        for (RunRenderer.Closest c : closest) {
            assertEquals(run.watched().least(c.measure()), c.value());
            long tick = run.watched().tickOf(c.measure());
            assertEquals(tick, c.tick());
            int i = (int) tick; // entry i is tick i
            assertEquals(tick, run.trajectory().tick(i));
            var middle = RunMarks.body(run.trajectory().x(i), run.trajectory().y(i), run.trajectory().heading(i)).centre();
            assertEquals(middle.x(), c.x(), 1e-12);
            assertEquals(middle.y(), c.y(), 1e-12);
            int px = (int) Math.floor(c.x() * SCALE);
            int py = (int) Math.floor(c.y() * SCALE);
            assertEquals(RunMarks.CLOSEST.getRGB() & 0xFFFFFF, picture.getRGB(px, py) & 0xFFFFFF,
                    c.measure() + "'s dot at (" + px + ", " + py + ")");
            assertTrue(c.text().startsWith(NearMissText.shortName(c.measure()) + " "), c.text());
            assertTrue(c.text().endsWith(" t=" + tick), c.text());
        }
        var parked = closest.get(1);
        assertTrue(parked.value() > 0 && parked.value() < 1, "the near miss: " + parked.text());
    }

    /** Map 866 leaves the road (faults/README.md, "How mature the car is": "a pull-out at low speed ... puts a corner off the far side"). */
    @Test
    void aMarginAnAccidentAlreadyMarksIsLeftToItsMarkerAndTheCaptionsLeastRhoIsThatAccidents() {
        Drawn run = Drawn.of(866);
        assertTrue(run.result().countsByType().get(AccidentType.LEAVEROAD) > 0, run.result().toString());
        assertTrue(run.watched().least(NearMiss.ROAD_EDGE) < 0);
        List<NearMiss> marked = RunRenderer.closest(run.trajectory(), run.result()).stream()
                .map(RunRenderer.Closest::measure).toList();
        assertFalse(marked.contains(NearMiss.ROAD_EDGE), marked.toString());
        assertTrue(marked.contains(NearMiss.PARKED_GAP), marked.toString());
        String rho = RunCaption.leastRho(run.result()).orElseThrow();
        // the only accident type the run had is the only one with ρ below 0
        assertTrue(rho.startsWith("-") && rho.endsWith(" m (" + AccidentType.LEAVEROAD.label() + ")"), rho);
    }

    @Test
    void aRunWithoutAccidentsHasALeastRhoOfZeroOrMore() {
        Drawn run = Drawn.of(1);
        String rho = RunCaption.leastRho(run.result()).orElseThrow();
        assertFalse(rho.startsWith("-"), rho);
        double least = Double.POSITIVE_INFINITY;
        for (AccidentType t : AccidentType.values()) {
            if (t != AccidentType.TIMEOUT) {
                least = Math.min(least, run.result().margins().robustness(t));
            }
        }
        assertTrue(rho.startsWith(String.format(java.util.Locale.ROOT, "%.2f m (", least)), rho + " against " + least);
    }
}
