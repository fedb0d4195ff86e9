package sitcov.viewer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Graphics2D;
import java.awt.image.BufferedImage;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import org.junit.jupiter.api.Test;
import sitcov.builtin.BuiltinCar;
import sitcov.builtin.BuiltinRuns;
import sitcov.faults.Fault;
import sitcov.judge.LiveRun;
import sitcov.judge.Simulator;
import sitcov.oracle.Accident;
import sitcov.oracle.NearMiss;
import sitcov.oracle.Outcome;
import sitcov.oracle.RunResult;
import sitcov.render.MapRenderer;
import sitcov.vehicles.AutonomousCar;
import sitcov.world.MapGenerator;
import sitcov.world.WorldMap;

/** The viewer's painting, headless: painted into an image, the car is where the model says it is. */
class RunPainterTest {
    private static BufferedImage paint(RunPainter painter) {
        BufferedImage image = new BufferedImage(painter.size().width, painter.size().height, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = image.createGraphics();
        painter.paint(g);
        g.dispose();
        return image;
    }

    /** The colour at the centre of the car's footprint, in the painted image. */
    private static int carPixel(RunPainter painter, BufferedImage image) {
        BuiltinCar car = (BuiltinCar) painter.run().scene().autonomousCar().controller();
        var centre = car.footprint().centre();
        int x = (int) Math.round(centre.x() * painter.pixelsPerMetre());
        int y = RunPainter.HEADER + (int) Math.round(centre.y() * painter.pixelsPerMetre());
        return image.getRGB(x, y) & 0xFFFFFF;
    }

    @Test
    void theCarIsPaintedWhereTheRunHasItAndFollowsItAsTheRunIsStepped() {
        WorldMap map = MapGenerator.generate(1);
        RunPainter painter = new RunPainter(BuiltinRuns.live(map, 1, Set.of()), "test", 4);
        for (int i = 0; i < 60; i++) {
            painter.run().step();
        }
        BufferedImage image = paint(painter);
        assertEquals(RunPainter.CAR.getRGB() & 0xFFFFFF, carPixel(painter, image), "the car's colour at its centre");
        BuiltinCar car = (BuiltinCar) painter.run().scene().autonomousCar().controller();
        assertTrue(car.cameraHits() > 0, "the camera saw markings");
        int yellow = 0;
        for (int h = 0; h < car.cameraHits(); h++) {
            int x = (int) Math.round(car.cameraHitX(h) * 4);
            int y = RunPainter.HEADER + (int) Math.round(car.cameraHitY(h) * 4);
            yellow += (image.getRGB(x, y) & 0xFFFFFF) == (RunPainter.CAMERA_HIT.getRGB() & 0xFFFFFF) ? 1 : 0;
        }
        assertTrue(yellow > 0, "the camera's hits are drawn where they are (a car may cover some)");
        var before = painter.run().scene().autonomousCar().footprint().centre();
        for (int i = 0; i < 40; i++) {
            painter.run().step();
        }
        var after = painter.run().scene().autonomousCar().footprint().centre();
        assertTrue(before.distanceTo(after.x(), after.y()) > 5, "the car moved " + before + " -> " + after);
        BufferedImage later = paint(painter);
        assertEquals(RunPainter.CAR.getRGB() & 0xFFFFFF, carPixel(painter, later));
        int oldX = (int) Math.round(before.x() * 4);
        int oldY = RunPainter.HEADER + (int) Math.round(before.y() * 4);
        assertTrue((later.getRGB(oldX, oldY) & 0xFFFFFF) != (RunPainter.CAR.getRGB() & 0xFFFFFF), "no car left behind");
    }

    @Test
    void aLiveRunSteppedToTheEndIsTheSimulatorsRun() {
        WorldMap map = MapGenerator.generate(7);
        LiveRun live = BuiltinRuns.live(map, 7, Set.of());
        while (live.step()) {
            // the viewer steps it frame by frame; here all at once
        }
        assertEquals(BuiltinRuns.run(map, 7), live.record().result());
    }

    @Test
    void onceARunHasEndedItsHeaderSaysHowInEachPane() {
        // seed 2: without faults the car reaches the Target; with fault 4 it leaves the road on the way
        WorldMap map = MapGenerator.generate(2);
        RunPainter twin = new RunPainter(BuiltinRuns.live(map, 2, Set.of()), "without the fault", 3);
        RunPainter faulty = new RunPainter(BuiltinRuns.live(map, 2, Set.of(Fault.ofId(4))), "with fault 4", 3);
        ViewerWindow window = new ViewerWindow(() -> List.of(twin, faulty));
        window.advance(1);
        assertTrue(window.painters().get(0).status().contains("km/h"), window.painters().get(0).status());
        for (int frame = 0; frame < 200; frame++) {
            window.advance(20);
        }
        RunResult free = BuiltinRuns.run(map, 2);
        RunResult withFault = BuiltinRuns.run(map, 2, Set.of(Fault.ofId(4)), (t, s, d) -> { }).result();
        assertEquals(Outcome.TARGET_REACHED, free.outcome());
        assertEquals(Outcome.TARGET_REACHED, withFault.outcome());
        Accident first = withFault.accidents().get(0);
        String twinStatus = window.painters().get(0).status();
        String faultyStatus = window.painters().get(1).status();
        assertEquals("Run over: Reached the Target at t=" + (free.ticks() - 1), twinStatus);
        assertTrue(faultyStatus.startsWith("Run over: Reached the Target at t=" + (withFault.ticks() - 1) + " · "),
                faultyStatus);
        assertTrue(faultyStatus.contains(first.type() + " at t=" + first.tick()), faultyStatus);
    }

    @Test
    void theSceneIsClippedToTheMapSoTheCaptionStaysAsTheMapDrewIt() {
        // seed 1 ends at the Target 10 m from the map's south edge: the LIDAR's 25 m reach goes past it
        WorldMap map = MapGenerator.generate(1);
        RunPainter painter = new RunPainter(BuiltinRuns.live(map, 1, Set.of()), "test", 3);
        while (painter.run().step()) {
            // to the end
        }
        assertTrue(painter.run().scene().autonomousCar().y() > 100 - 25, "the case this test needs");
        BufferedImage image = paint(painter);
        BufferedImage bare = new MapRenderer(3).renderWithoutTraffic(map);
        int differing = 0;
        for (int y = MapRenderer.worldHeightPixels(3); y < bare.getHeight(); y++) {
            for (int x = 0; x < bare.getWidth(); x++) {
                differing += image.getRGB(x, RunPainter.HEADER + y) != bare.getRGB(x, y) ? 1 : 0;
            }
        }
        assertEquals(0, differing, "caption pixels painted over");
    }

    /**
     * Map 1's car passes a parked car closest at some tick T: the header gives the least gap so far,
     * larger before T than from T on, and once the run is over the run's own kept value.
     */
    @Test
    void theHeaderGivesTheNearMissesSoFarAsTheRunGoesOn() {
        WorldMap map = MapGenerator.generate(1);
        RunPainter painter = new RunPainter(BuiltinRuns.live(map, 1, Set.of()), "test", 3);
        assertEquals("closest so far: nothing yet", painter.nearMisses());
        RunResult whole = BuiltinRuns.run(map, 1);
        LiveRun probe = BuiltinRuns.live(map, 1, Set.of());
        while (probe.step()) {
            // to the end, to learn when the least gap was reached
        }
        long closest = probe.nearMisses().tickOf(NearMiss.PARKED_GAP);
        assertTrue(closest > 10, "the case this test needs: " + closest);
        while (painter.run().tick() < closest - 1) {
            painter.run().step();
        }
        double before = painter.run().nearMisses().least(NearMiss.PARKED_GAP);
        assertTrue(before > whole.margins().least(NearMiss.PARKED_GAP), before + " before tick " + closest);
        assertTrue(painter.nearMisses().contains("parked car " + String.format(Locale.ROOT, "%.2f m", before)),
                painter.nearMisses());
        while (painter.run().step()) {
            // to the end
        }
        String end = painter.nearMisses();
        assertTrue(end.startsWith("closest so far: moving car "), end);
        assertTrue(end.contains(" · parked car " + String.format(Locale.ROOT, "%.2f m",
                whole.margins().least(NearMiss.PARKED_GAP)) + " · "), end);
        assertTrue(end.contains(" · least ρ "), end);
        assertFalse(end.contains("unknown"), end);
    }

    /** How many pixels of the image are painted in {@code colour}. */
    private static int pixelsOf(BufferedImage image, java.awt.Color colour) {
        int n = 0;
        for (int y = 0; y < image.getHeight(); y++) {
            for (int x = 0; x < image.getWidth(); x++) {
                n += (image.getRGB(x, y) & 0xFFFFFF) == (colour.getRGB() & 0xFFFFFF) ? 1 : 0;
            }
        }
        return n;
    }

    /** Map 3's fault-free run, replayed from its commands as if its controller had taken only {@code sensors}, stepped 80 ticks. */
    private static RunPainter replayedTaking(Set<sitcov.control.Sensor> sensors) {
        WorldMap map = MapGenerator.generate(3);
        var commands = BuiltinRuns.run(map, 3, Set.of(), (t, s, d) -> { }).commands();
        commands.sensors(sensors);
        RunPainter painter = new RunPainter(LiveRun.replaying(map, 3, commands, Long.MAX_VALUE), "replayed", 4);
        for (int i = 0; i < 80; i++) {
            painter.run().step();
        }
        return painter;
    }

    @Test
    void theObservationsRadarTracksAreDrawnWhereTheyAre() {
        RunPainter painter = replayedTaking(sitcov.control.Sensor.all());
        var tracks = painter.run().telemetry().observation().traffic();
        assertTrue(tracks.size() >= 2, "the case this test needs: other cars within the radar's range, " + tracks.size());
        assertTrue(painter.run().detector().accidents().isEmpty(), "no accident ring covers a track");
        BufferedImage image = paint(painter);
        for (var v : tracks) {
            int x = (int) Math.round(v.x() * 4);
            int y = RunPainter.HEADER + (int) Math.round(v.y() * 4);
            assertEquals(RunPainter.SENSED.getRGB() & 0xFFFFFF, image.getRGB(x, y) & 0xFFFFFF,
                    "vehicle " + v.id() + "'s track at its front (" + v.x() + ", " + v.y() + ")");
        }
        int obstacles = painter.run().telemetry().observation().obstacles().size();
        assertEquals("observes " + tracks.size() + " radar tracks · " + obstacles + " obstacle" + (obstacles == 1 ? "" : "s")
                + " · camera · LIDAR", painter.observed());
    }

    @Test
    void onlyTheSensorsTheControllerTookAreDrawn() {
        int tracksAndObstacles = pixelsOf(paint(replayedTaking(Set.of(sitcov.control.Sensor.RADAR,
                sitcov.control.Sensor.OBSTACLES))), RunPainter.SENSED);
        int obstaclesOnly = pixelsOf(paint(replayedTaking(Set.of(sitcov.control.Sensor.OBSTACLES))), RunPainter.SENSED);
        RunPainter blind = replayedTaking(Set.of());
        BufferedImage none = paint(blind);
        assertTrue(obstaclesOnly > 0, "the parked cars within range are outlined");
        assertTrue(tracksAndObstacles > obstaclesOnly, "the tracks add their own: " + tracksAndObstacles + " > " + obstaclesOnly);
        assertEquals(0, pixelsOf(none, RunPainter.SENSED), "a controller that took no sensor saw no track and no obstacle");
        assertEquals(0, pixelsOf(none, RunPainter.CAMERA_HIT), "nor the camera's hits");
        assertEquals("observes no sensor (pose, map, Target, signals)", blind.observed());
        assertTrue(pixelsOf(paint(replayedTaking(Set.of(sitcov.control.Sensor.CAMERA))), RunPainter.CAMERA_HIT) > 0,
                "the camera's hits, where it took the camera");
    }
}
