package sitcov.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Color;
import java.awt.Dimension;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.stream.Stream;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import sitcov.builtin.BuiltinRuns;
import sitcov.judge.Simulator;
import sitcov.oracle.Accident;
import sitcov.oracle.AccidentType;
import sitcov.oracle.Outcome;
import sitcov.oracle.RunResult;
import sitcov.world.Dimensions;
import sitcov.world.MapGenerator;
import sitcov.world.WorldMap;

class RunRendererTest {

    private static final int SCALE = MapRenderer.DEFAULT_SCALE;
    private static final WorldMap MAP = MapGenerator.generate(3);

    private static TrajectoryRecorder trajectory;
    private static RunResult result;
    private static BufferedImage plain;
    private static BufferedImage picture;

    @BeforeAll
    static void runAndRenderOnce() {
        trajectory = new TrajectoryRecorder();
        result = BuiltinRuns.run(MAP, 100, Set.of(), trajectory).result();
        plain = new MapRenderer(SCALE).render(MAP);
        picture = new RunRenderer(SCALE).render(MAP, trajectory, result);
    }

    /** The last recorded position that lies on the map (a car may drive off it). */
    private static int lastOnTheMap() {
        for (int i = trajectory.ticks() - 1; i >= 0; i--) {
            if (trajectory.x(i) > 1 && trajectory.x(i) < Dimensions.WORLD_WIDTH - 1
                    && trajectory.y(i) > 1 && trajectory.y(i) < Dimensions.WORLD_HEIGHT - 1) {
                return i;
            }
        }
        throw new AssertionError("the car was never on the map");
    }

    @Test
    void rendersTheWholeMapAtTheSizeTheMapRendererGivesIt() {
        assertEquals(MapRenderer.imageSize(SCALE), new Dimension(picture.getWidth(), picture.getHeight()));
        BufferedImage small = new RunRenderer(2).render(MAP, trajectory, result);
        assertEquals(MapRenderer.imageSize(2), new Dimension(small.getWidth(), small.getHeight()));
    }

    @Test
    void drawsThePathWhereTheCarDroveOverThePlainMap() {
        int last = lastOnTheMap();
        int x = (int) Math.round(trajectory.x(last) * SCALE);
        int y = (int) Math.round(trajectory.y(last) * SCALE);
        assertNotEquals(plain.getRGB(x, y), picture.getRGB(x, y), "nothing drawn at the car's last position");
        int start = (int) Math.round(trajectory.x(0) * SCALE);
        int startY = (int) Math.round(trajectory.y(0) * SCALE);
        assertNotEquals(plain.getRGB(start, startY), picture.getRGB(start, startY), "nothing drawn at its first");
    }

    @Test
    void leavesTheMapAloneFarFromThePath() {
        // the north-west corner of seed 3 is grass the car never came near
        assertTrue(trajectory.y(0) > 20 && trajectory.x(0) > 20);
        for (int i = 0; i < trajectory.ticks(); i++) {
            assertTrue(trajectory.x(i) > 12 || trajectory.y(i) > 12, "the car came near the corner at " + i);
        }
        assertEquals(plain.getRGB(5 * SCALE, 5 * SCALE), picture.getRGB(5 * SCALE, 5 * SCALE));
    }

    @Test
    void marksEachAccidentInItsTypesOwnColour() {
        RunResult made = new RunResult(MAP.seed(), 100, Outcome.TIMEOUT, List.of(
                new Accident(52, AccidentType.LEAVEROAD, 6, 6, -1),
                new Accident(70, AccidentType.CROSSCENTRELINE, 40, 94, -1)), Map.of(), 5000);
        BufferedImage image = new RunRenderer(SCALE).render(MAP, new TrajectoryRecorder(), made);
        assertColour(RunMarks.markerColour(AccidentType.LEAVEROAD), image, 6 * SCALE, 6 * SCALE);
        assertColour(RunMarks.markerColour(AccidentType.CROSSCENTRELINE), image, 40 * SCALE, 94 * SCALE);
        assertNotEquals(RunMarks.markerColour(AccidentType.LEAVEROAD), RunMarks.markerColour(AccidentType.CROSSCENTRELINE));
    }

    @Test
    void writesItsOwnCaptionInsteadOfTheMapsOne() {
        int top = MapRenderer.worldHeightPixels(SCALE) + SCALE;
        int differing = 0;
        for (int y = top; y < picture.getHeight(); y++) {
            for (int x = 0; x < picture.getWidth(); x++) {
                if (picture.getRGB(x, y) != plain.getRGB(x, y)) {
                    differing++;
                }
            }
        }
        assertTrue(differing > 500, "only " + differing + " caption pixels differ from the map's caption");
    }

    @Test
    void aWindowIsASquareOfTwiceTheRadiusAtItsOwnScale() {
        int last = lastOnTheMap();
        RunRenderer renderer = new RunRenderer(SCALE);
        BufferedImage window = renderer.renderWindow(MAP, trajectory, result, trajectory.x(last), trajectory.y(last), 10, 20);
        assertEquals(400, window.getWidth());
        assertEquals(400, window.getHeight());
        BufferedImage small = renderer.renderWindow(MAP, trajectory, result, 50, 50, 2.5, 8);
        assertEquals(new Dimension(40, 40), new Dimension(small.getWidth(), small.getHeight()));
    }

    @Test
    void aWindowShowsTheCarWhereItWas() {
        int last = lastOnTheMap();
        double cx = trajectory.x(last);
        double cy = trajectory.y(last);
        RunRenderer renderer = new RunRenderer(SCALE);
        BufferedImage withRun = renderer.renderWindow(MAP, trajectory, result, cx, cy, 10, 20);
        RunResult nothing = new RunResult(MAP.seed(), 100, Outcome.TIMEOUT, List.of(), Map.of(), 0);
        BufferedImage withoutRun = renderer.renderWindow(MAP, new TrajectoryRecorder(), nothing, cx, cy, 10, 20);
        assertNotEquals(withoutRun.getRGB(200, 200), withRun.getRGB(200, 200));
    }

    @Test
    void refusesScalesAndWindowsItCannotDraw() {
        assertThrows(IllegalArgumentException.class, () -> new RunRenderer(0));
        assertThrows(IllegalArgumentException.class, () -> new RunRenderer(MapRenderer.MAX_SCALE + 1));
        RunRenderer renderer = new RunRenderer(SCALE);
        assertThrows(IllegalArgumentException.class, () -> renderer.renderWindow(MAP, trajectory, result, 50, 50, 0, 20));
        assertThrows(IllegalArgumentException.class, () -> renderer.renderWindow(MAP, trajectory, result, 50, 50, 10, 0));
    }

    @Test
    void writesAPngThatReadsBackAndLeavesNoTemporaryFile(@TempDir Path dir) throws IOException {
        Path file = dir.resolve("run.png");
        Files.writeString(file, "not a picture");
        new RunRenderer(SCALE).writePng(picture, file);
        BufferedImage back = ImageIO.read(file.toFile());
        assertEquals(picture.getWidth(), back.getWidth());
        assertEquals(picture.getRGB(100, 100), back.getRGB(100, 100));
        try (Stream<Path> files = Files.list(dir)) {
            assertEquals(List.of(file), files.toList());
        }
    }

    @Test
    void labelsOfMarksCrowdedRoundOnePointNeitherOverlapOneAnotherNorTheTargetsLabel() {
        var target = MAP.layout().target().orElseThrow().position();
        double x = target.x();
        double y = target.y();
        // four accidents 4 m apart round the Target (far enough apart for a label each), a ring on one
        // of them and one singled out: seven labels with the map's own Target and AR, besides the
        // closest approaches' labels
        Accident singled = new Accident(4999, AccidentType.TIMEOUT, x - 4, y, -1);
        RunResult crowded = new RunResult(MAP.seed(), 100, Outcome.TIMEOUT, List.of(
                new Accident(52, AccidentType.LEAVEROAD, x + 4, y, -1),
                new Accident(60, AccidentType.CROSSCENTRELINE, x, y + 4, -1),
                new Accident(70, AccidentType.CLASHWITHOBSTACLE, x, y - 4, -1),
                singled), Map.of(), 5000);
        RunRenderer.Highlights highlights = new RunRenderer.Highlights(
                List.of(new RunRenderer.Ring(x - 4, y, Color.ORANGE, "fault 17 first acts, t=189")),
                java.util.Optional.of(singled), Color.RED, "first new accident: ");
        List<java.awt.geom.Rectangle2D> labels = new RunRenderer(SCALE).draw(MAP, trajectory, crowded, highlights).labels();
        // and the run's closest approaches: a label for each place, those within 18 pixels of an earlier one sharing it
        List<RunRenderer.Closest> closest = RunRenderer.closest(trajectory, crowded);
        assertEquals(4, closest.size());
        List<RunRenderer.Closest> places = new java.util.ArrayList<>();
        for (RunRenderer.Closest c : closest) {
            if (places.stream().noneMatch(p -> Math.hypot(p.x() - c.x(), p.y() - c.y()) * SCALE < 18)) {
                places.add(c);
            }
        }
        assertTrue(places.size() < closest.size(), "the case this test needs: two closest approaches at one place");
        assertEquals(7 + places.size(), labels.size(), "Target, AR, four accidents, the ring and the closest approaches");
        for (int i = 0; i < labels.size(); i++) {
            for (int j = i + 1; j < labels.size(); j++) {
                assertFalse(labels.get(i).intersects(labels.get(j)), "labels " + i + " and " + j + " overlap: "
                        + labels.get(i) + " " + labels.get(j));
            }
        }
    }

    private static void assertColour(Color expected, BufferedImage image, int x, int y) {
        Color actual = new Color(image.getRGB(x, y));
        int distance = Math.abs(actual.getRed() - expected.getRed()) + Math.abs(actual.getGreen() - expected.getGreen())
                + Math.abs(actual.getBlue() - expected.getBlue());
        assertTrue(distance <= 30, "pixel " + x + "," + y + " is " + actual + ", expected about " + expected);
    }
}
