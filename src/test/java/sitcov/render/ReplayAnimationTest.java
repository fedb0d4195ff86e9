package sitcov.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Color;
import java.awt.image.BufferedImage;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import sitcov.builtin.BuiltinRuns;
import sitcov.faults.Fault;
import sitcov.geom.Box;
import sitcov.judge.Simulator;
import sitcov.oracle.Accident;
import sitcov.oracle.AccidentType;
import sitcov.oracle.Outcome;
import sitcov.oracle.RunResult;
import sitcov.world.MapGenerator;
import sitcov.world.WorldMap;

class ReplayAnimationTest {
    /** Frames every 5 ticks to {@code end}: the car 0.1 m further each tick up to {@code stopsAt}, then standing. */
    private static ReplayAnimation.Side side(long end, long stopsAt, List<Accident> accidents, Outcome outcome) {
        List<FrameRecorder.Frame> frames = new ArrayList<>();
        for (long t = 0; t <= end; t += 5) {
            frames.add(new FrameRecorder.Frame(t, Box.centred(10 + 0.1 * Math.min(t, stopsAt), 50, 90, 2, 2),
                    List.of(), 0));
        }
        RunResult result = new RunResult(1, 1, outcome, accidents, Map.of(), end + 1);
        return new ReplayAnimation.Side("a run", new TrajectoryRecorder(), frames, result, Optional.empty(), Optional.empty());
    }

    private static List<Long> ticks(List<ReplayAnimation.Shot> shots) {
        return shots.stream().map(ReplayAnimation.Shot::tick).toList();
    }

    @Test
    void aCarStandingStillIsShownForAFewFramesThenSkippedToTheEndAndTheSkipIsSaid() {
        ReplayAnimation.Side stops = side(1000, 50, List.of(new Accident(999, AccidentType.TIMEOUT, 15, 50, -1)),
                Outcome.TIMEOUT);
        ReplayAnimation.Side ends = side(30, 30, List.of(), Outcome.TARGET_REACHED);
        List<ReplayAnimation.Shot> shots = ReplayAnimation.shots(List.of(ends, stops));
        List<Long> expected = new ArrayList<>();
        for (long t = 0; t <= 50 + 5L * ReplayAnimation.HOLD; t += 5) {
            expected.add(t); // moving to 50, then standing for HOLD frames
        }
        expected.add(1000L);
        assertEquals(expected, ticks(shots));
        assertEquals(50 + 5L * ReplayAnimation.HOLD, shots.get(shots.size() - 1).skippedFrom());
        assertTrue(shots.subList(0, shots.size() - 1).stream().noneMatch(ReplayAnimation.Shot::afterSkip));
    }

    @Test
    void anAccidentDuringAStillStretchGetsItsOwnFrame() {
        ReplayAnimation.Side stops = side(1000, 50, List.of(new Accident(502, AccidentType.CLASHWITHOTHERCAR, 15, 50, 3),
                new Accident(999, AccidentType.TIMEOUT, 15, 50, -1)), Outcome.TIMEOUT);
        List<ReplayAnimation.Shot> shots = ReplayAnimation.shots(List.of(stops));
        int at = ticks(shots).indexOf(505L);
        assertTrue(at > 0, "no frame shows the accident at 502: " + ticks(shots));
        assertTrue(shots.get(at).afterSkip(), "the still ticks before it were skipped");
        assertTrue(ticks(shots).size() < 2 * (ReplayAnimation.HOLD + 1) + 12, ticks(shots).toString());
    }

    @Test
    void aLongBusyRunIsThinnedToTheMostFramesAllowedEndingOnItsLastTick() {
        ReplayAnimation.Side busy = side(5000, 5000, List.of(), Outcome.TIMEOUT);
        List<Long> ticks = ticks(ReplayAnimation.shots(List.of(busy)));
        assertEquals(ReplayAnimation.MAX_FRAMES, ticks.size());
        assertEquals(0L, ticks.get(0));
        assertEquals(5000L, ticks.get(ticks.size() - 1));
    }

    @Test
    void framesShowEachAccidentFromItsTickOnAndAnEndedRunHeldAtItsEnd(@TempDir Path dir) throws Exception {
        // seed 2: the fault-free run reaches the Target at t=73; with fault 4 the car leaves the road at t=9
        WorldMap map = MapGenerator.generate(2);
        TrajectoryRecorder freePath = new TrajectoryRecorder();
        FrameRecorder freeFrames = new FrameRecorder(5);
        RunResult free = BuiltinRuns.run(map, 2, Set.of(), (t, s, d) -> {
            freePath.afterTick(t, s, d);
            freeFrames.afterTick(t, s, d);
        }).result();
        TrajectoryRecorder faultyPath = new TrajectoryRecorder();
        FrameRecorder faultyFrames = new FrameRecorder(5);
        Fault fault = Fault.ofId(4);
        var faulty = BuiltinRuns.run(map, 2, Set.of(fault), (t, s, d) -> {
            faultyPath.afterTick(t, s, d);
            faultyFrames.afterTick(t, s, d);
        });
        Accident first = faulty.result().accidents().get(0);
        assertTrue(first.tick() > 5 && faulty.result().ticks() > free.ticks(), "the case this test needs: " + faulty.result());
        List<ReplayAnimation.Side> sides = List.of(
                new ReplayAnimation.Side("without the fault", freePath, freeFrames.frames(), free, Optional.empty(),
                        Optional.empty()),
                new ReplayAnimation.Side("with fault 4", faultyPath, faultyFrames.frames(), faulty.result(),
                        Optional.of(faulty.activations().get(fault.ordinal())), Optional.of(first)));
        Path file = dir.resolve("replay.gif");
        ReplayAnimation.write(map, sides, file);
        int early = ticks(ReplayAnimation.shots(sides)).indexOf(5L);
        GifFile gif = GifFile.read(file, early, -1);
        BufferedImage before = gif.shown().get(0);
        BufferedImage last = gif.shown().get(1);

        int right = (before.getWidth() + ReplayAnimation.GAP) / 2;
        int ax = right + (int) Math.round(first.x() * ReplayAnimation.SCALE);
        int ay = ReplayAnimation.HEADER + (int) Math.round(first.y() * ReplayAnimation.SCALE) + 1;
        int marker = RunMarks.markerColour(first.type()).getRGB() & 0xFFFFFF;
        assertNotEquals(marker, before.getRGB(ax, ay) & 0xFFFFFF, "the accident is marked before it happens");
        assertEquals(marker, last.getRGB(ax, ay) & 0xFFFFFF, "the accident is not marked after it happened");

        // the fault-free run ended first: its car stays where it stopped
        int end = freePath.ticks() - 1;
        Box car = RunMarks.body(freePath.x(end), freePath.y(end), freePath.heading(end));
        int cx = (int) Math.round(car.centreX() * ReplayAnimation.SCALE);
        int cy = ReplayAnimation.HEADER + (int) Math.round(car.centreY() * ReplayAnimation.SCALE);
        assertEquals(MapStyle.AUTONOMOUS_CAR.getRGB() & 0xFFFFFF, last.getRGB(cx, cy) & 0xFFFFFF);

        // the path driven so far: where the fault-free car was at t=40, the last frame shows a path colour
        int px = (int) Math.round(freePath.x(40) * ReplayAnimation.SCALE);
        int py = ReplayAnimation.HEADER + (int) Math.round(freePath.y(40) * ReplayAnimation.SCALE);
        Color path = new Color(last.getRGB(px, py));
        assertTrue(near(path, RunMarks.DRIVING) || near(path, RunMarks.CROSSING), "no path at t=40: " + path);

        // after the first frame only what changed is stored; the last frame stays longest
        assertTrue(gif.regions().get(1).width * gif.regions().get(1).height < before.getWidth() * before.getHeight());
        assertEquals(ReplayAnimation.LAST_DELAY, gif.delays().get(gif.frames() - 1));
    }

    private static boolean near(Color a, Color b) {
        return Math.abs(a.getRed() - b.getRed()) + Math.abs(a.getGreen() - b.getGreen())
                + Math.abs(a.getBlue() - b.getBlue()) < 60;
    }
}
