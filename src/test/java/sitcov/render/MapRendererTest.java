package sitcov.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Color;
import java.awt.Dimension;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.HashSet;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import java.util.stream.Stream;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import sitcov.geom.Box;
import sitcov.geom.Vec2;
import sitcov.world.Axis;
import sitcov.world.Dimensions;
import sitcov.world.Junction;
import sitcov.world.Layout;
import sitcov.world.MapGenerator;
import sitcov.world.Road;
import sitcov.world.StartPose;
import sitcov.world.Target;
import sitcov.world.WorldMap;

class MapRendererTest {

    private static final int SCALE = MapRenderer.DEFAULT_SCALE;
    private static final WorldMap SEED_1 = MapGenerator.generate(1);

    @Test
    void rendersAnImageOfTheExpectedSize() {
        BufferedImage image = new MapRenderer().render(SEED_1);
        assertEquals(MapRenderer.imageSize(SCALE), new Dimension(image.getWidth(), image.getHeight()));
        BufferedImage small = new MapRenderer(2).render(SEED_1);
        assertEquals(MapRenderer.imageSize(2), new Dimension(small.getWidth(), small.getHeight()));
    }

    @Test
    void imageSizeIsTheWorldAtScalePlusACaptionStripBelowIt() {
        Dimension size = MapRenderer.imageSize(SCALE);
        assertEquals(200 * SCALE, size.width);
        assertTrue(size.height > 100 * SCALE, "no room for the caption: " + size);
        assertTrue(MapRenderer.imageSize(10).height > size.height);
    }

    @Test
    void writesAPngThatReadsBackWithTheSameSizeAndLeavesNoTemporaryFile(@TempDir Path dir) throws IOException {
        Path file = dir.resolve("seed-1.png");
        new MapRenderer().writePng(SEED_1, file);
        assertTrue(Files.size(file) > 0);
        BufferedImage back = ImageIO.read(file.toFile());
        assertEquals(MapRenderer.imageSize(SCALE), new Dimension(back.getWidth(), back.getHeight()));
        try (Stream<Path> files = Files.list(dir)) {
            assertEquals(List.of(file), files.toList());
        }
    }

    @Test
    void writingOverAnExistingFileReplacesIt(@TempDir Path dir) throws IOException {
        Path file = dir.resolve("map.png");
        Files.writeString(file, "not a picture");
        new MapRenderer(2).writePng(SEED_1, file);
        BufferedImage back = ImageIO.read(file.toFile());
        assertEquals(MapRenderer.imageSize(2).width, back.getWidth());
    }

    @Test
    void writingIntoAMissingFolderFailsWithoutLeavingAFile(@TempDir Path dir) {
        Path file = dir.resolve("missing").resolve("map.png");
        assertThrows(IOException.class, () -> new MapRenderer().writePng(SEED_1, file));
        assertFalse(Files.exists(file));
    }

    @Test
    void drawsManyColoursNotABlankImage() {
        BufferedImage image = new MapRenderer().render(SEED_1);
        Set<Integer> colours = new HashSet<>();
        for (int y = 0; y < image.getHeight(); y += 2) {
            for (int x = 0; x < image.getWidth(); x += 2) {
                colours.add(image.getRGB(x, y) & 0xFFFFFF);
            }
        }
        assertTrue(colours.size() > 20, "only " + colours.size() + " colours");
    }

    @Test
    void drawsGrassWhereThereIsNoRoad() {
        BufferedImage image = new MapRenderer().render(SEED_1);
        // seed 1's roads all lie in the south-east; its north-west corner is open grass
        assertTrue(SEED_1.layout().roads().stream().noneMatch(r -> r.surface().minX() < 40 && r.surface().minY() < 30));
        assertColour(MapStyle.GRASS, image, 5 * SCALE + 3, 5 * SCALE + 3);
    }

    @Test
    void marksTheTargetInTheTargetColour() {
        BufferedImage image = new MapRenderer().render(SEED_1);
        Vec2 target = SEED_1.layout().target().orElseThrow().position();
        assertColour(MapStyle.TARGET, image, (int) Math.round(target.x() * SCALE), (int) Math.round(target.y() * SCALE));
    }

    @Test
    void drawsTheAutonomousCarAtItsStartInItsOwnColour() {
        BufferedImage image = new MapRenderer().render(SEED_1);
        StartPose start = SEED_1.layout().carStart().orElseThrow();
        Vec2 centre = start.footprint(Dimensions.AUTONOMOUS_CAR_LENGTH, Dimensions.AUTONOMOUS_CAR_WIDTH).centre();
        int x = (int) Math.round(centre.x() * SCALE);
        int y = (int) Math.round(centre.y() * SCALE);
        assertColour(MapStyle.AUTONOMOUS_CAR, image, x, y);
        // and its heading arrow lies ahead of it, beyond its front
        Vec2 ahead = start.position().moved(start.heading().bearing(), 1.0);
        assertColour(MapStyle.AUTONOMOUS_CAR, image, (int) Math.round(ahead.x() * SCALE), (int) Math.round(ahead.y() * SCALE));
    }

    @Test
    void drawsParkedAndMovingCarsInTheirColours() {
        BufferedImage image = new MapRenderer().render(SEED_1);
        Vec2 parked = SEED_1.layout().parkedCars().get(0).centre();
        assertColour(MapStyle.PARKED_CAR, image, (int) Math.round(parked.x() * SCALE), (int) Math.round(parked.y() * SCALE));
        StartPose moving = SEED_1.movingCars().get(0);
        // the rear half of the body: the front half holds the white heading mark
        Box body = moving.footprint(Dimensions.CAR_LENGTH, Dimensions.CAR_WIDTH);
        Vec2 rear = body.centre().moved(moving.heading().bearing(), -1.5);
        assertColour(MapStyle.MOVING_CAR, image, (int) Math.round(rear.x() * SCALE), (int) Math.round(rear.y() * SCALE));
    }

    @Test
    void withoutTrafficTheMovingCarsAreNotDrawnButTheCaptionStillCountsThemAsTheMapHasThem() {
        assertFalse(SEED_1.movingCars().isEmpty(), "seed 1 must have moving cars for this test");
        BufferedImage full = new MapRenderer().render(SEED_1);
        BufferedImage bare = new MapRenderer().renderWithoutTraffic(SEED_1);
        StartPose moving = SEED_1.movingCars().get(0);
        Vec2 rear = moving.footprint(Dimensions.CAR_LENGTH, Dimensions.CAR_WIDTH).centre()
                .moved(moving.heading().bearing(), -1.5);
        int x = (int) Math.round(rear.x() * SCALE);
        int y = (int) Math.round(rear.y() * SCALE);
        assertColour(MapStyle.MOVING_CAR, full, x, y);
        assertColour(MapStyle.ASPHALT, bare, x, y);
        // the caption (seed, counts "N moving cars", legend) is the full map's, pixel for pixel
        for (int row = MapRenderer.worldHeightPixels(SCALE); row < full.getHeight(); row++) {
            for (int col = 0; col < full.getWidth(); col++) {
                assertEquals(full.getRGB(col, row), bare.getRGB(col, row), "caption pixel " + col + "," + row);
            }
        }
    }

    @Test
    void differentSeedsRenderDifferentImages() {
        MapRenderer renderer = new MapRenderer(2);
        assertFalse(samePixels(renderer.render(MapGenerator.generate(1)), renderer.render(MapGenerator.generate(2))));
    }

    @Test
    void theSameMapAlwaysRendersTheSamePixels() {
        MapRenderer renderer = new MapRenderer(3);
        assertTrue(samePixels(renderer.render(SEED_1), renderer.render(MapGenerator.generate(1))));
    }

    @Test
    void rendersAHandBuiltMapWithoutTargetOrCarStart() {
        Road road = new Road(0, Axis.EAST_WEST, 50, 20, 180);
        List<Junction> ends = List.of(new Junction(0, new Vec2(23, 50), 0, 23, 0, 0),
                new Junction(1, new Vec2(177, 50), 0, 0, 0, 23));
        Layout layout = new Layout(0, List.of(road), ends, List.of(), Optional.empty(), Optional.empty(), 0, 0, List.of());
        WorldMap map = new WorldMap(layout, List.of(), 0, List.of());

        BufferedImage image = new MapRenderer().render(map);

        assertEquals(MapRenderer.imageSize(SCALE), new Dimension(image.getWidth(), image.getHeight()));
        assertColour(MapStyle.ASPHALT, image, 100 * SCALE, (int) (51.5 * SCALE));
        int worldHeight = 100 * SCALE;
        for (int y = 0; y < worldHeight; y++) {
            for (int x = 0; x < image.getWidth(); x++) {
                int rgb = image.getRGB(x, y) & 0xFFFFFF;
                if (rgb == (MapStyle.AUTONOMOUS_CAR.getRGB() & 0xFFFFFF) || rgb == (MapStyle.TARGET.getRGB() & 0xFFFFFF)) {
                    throw new AssertionError("a car or Target was drawn at " + x + "," + y + " on a map without one");
                }
            }
        }
    }

    @Test
    void aTargetAloneStillRenders() {
        Road road = new Road(0, Axis.NORTH_SOUTH, 100, 0, 100);
        Layout layout = new Layout(0, List.of(road), List.of(), List.of(),
                Optional.of(new Target(new Vec2(101.5, 50), 0)), Optional.empty(), 0, 0, List.of());
        BufferedImage image = new MapRenderer().render(new WorldMap(layout, List.of(), 0, List.of()));
        assertColour(MapStyle.TARGET, image, (int) (101.5 * SCALE), 50 * SCALE);
    }

    @Test
    void refusesScalesOutsideTheSupportedRange() {
        assertThrows(IllegalArgumentException.class, () -> new MapRenderer(0));
        assertThrows(IllegalArgumentException.class, () -> new MapRenderer(MapRenderer.MAX_SCALE + 1));
        assertThrows(IllegalArgumentException.class, () -> MapRenderer.imageSize(-1));
    }

    private static void assertColour(Color expected, BufferedImage image, int x, int y) {
        Color actual = new Color(image.getRGB(x, y));
        int distance = Math.abs(actual.getRed() - expected.getRed()) + Math.abs(actual.getGreen() - expected.getGreen())
                + Math.abs(actual.getBlue() - expected.getBlue());
        assertTrue(distance <= 30, "pixel " + x + "," + y + " is " + actual + ", expected about " + expected);
    }

    private static boolean samePixels(BufferedImage a, BufferedImage b) {
        if (a.getWidth() != b.getWidth() || a.getHeight() != b.getHeight()) {
            return false;
        }
        int[] pa = a.getRGB(0, 0, a.getWidth(), a.getHeight(), null, 0, a.getWidth());
        int[] pb = b.getRGB(0, 0, b.getWidth(), b.getHeight(), null, 0, b.getWidth());
        return Arrays.equals(pa, pb);
    }
}
