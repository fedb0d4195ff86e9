package sitcov.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

class SituationFileTest {
    @TempDir
    Path folder;

    @Test
    void writingAndReadingBackGivesAnEqualMapForManySeeds() throws Exception {
        for (long seed = 1; seed <= 300; seed++) {
            WorldMap map = MapGenerator.generate(seed * 7919);
            assertEquals(map, SituationFile.parse(SituationFile.format(map).lines().toList(), "seed " + seed),
                    "seed " + seed * 7919);
        }
    }

    @Test
    void aFileOnDiskRoundTripsAndAHandBuiltMapToo() throws Exception {
        Path file = folder.resolve("tee.situation");
        WorldMap tee = Situations.withoutTraffic(Situations.tee());

        Files.writeString(file, SituationFile.format(tee));

        assertEquals(tee, SituationFile.read(file));
        assertEquals(List.of(file), listFolder(), "no temporary file is left behind");
    }

    @Test
    void theFileIsHumanReadable() {
        String text = SituationFile.format(Situations.withoutTraffic(Situations.tee()));
        assertTrue(text.startsWith("sitcov-situation 1\n"), text);
        assertTrue(text.contains("\nroad 1 NORTH_SOUTH 100.0 30.0 90.0\n"), text);
        assertTrue(text.contains("\ncar-start 40.0 28.5 EAST\n"), text);
        assertTrue(text.endsWith("end\n"));
    }

    static Stream<Arguments> malformedFiles() {
        String good = SituationFile.format(Situations.withoutTraffic(Situations.tee()));
        return Stream.of(
                Arguments.of("", 0, "empty file"),
                Arguments.of("hello world\n", 1, "expected the first line 'sitcov-situation 1'"),
                Arguments.of("sitcov-situation 2\n", 1, "version 2 is not supported"),
                Arguments.of(good.replace("end\n", ""), 0, "without its closing 'end'"),
                Arguments.of(good.replace("seed 0", "seed zero"), 3, "expected a whole number for SEED, found 'zero'"),
                Arguments.of(good.replace("road 1 NORTH_SOUTH", "road 1 DIAGONAL"), 7, "expected an axis"),
                Arguments.of(good.replace("road 1 NORTH_SOUTH 100.0", "road 1 NORTH_SOUTH"), 7, "expected 'road ID AXIS CENTRE FROM TO'"),
                Arguments.of(good.replace("road 1 ", "road 5 "), 7, "expected road id 1"),
                Arguments.of(good.replace("30.0 90.0", "90.0 30.0"), 7, "expected FROM < TO"),
                Arguments.of(good.replace("car-start 40.0 28.5 EAST", "car-start 40.0 28.5 UP"), 15, "expected a heading"),
                Arguments.of(good.replace("target 101.5 70.0 1", "target 101.5 NaN 1"), 14, "expected a number for Y"),
                Arguments.of(good.replace("target 101.5 70.0 1", "target 101.5 70.0 9"), 14, "expected the id of a road"),
                Arguments.of(good.replace("end\n", "teleporter 1 2\nend\n"), 16, "found 'teleporter'"),
                Arguments.of(good + "road 2 EAST_WEST 1 2 3\n", 17, "expected nothing after 'end'"),
                Arguments.of(good.replace("seed 0\n", "seed 0\nseed 1\n"), 4, "a second 'seed' line"));
    }

    @ParameterizedTest(name = "[{index}] {2}")
    @MethodSource("malformedFiles")
    void aMalformedFileIsRefusedNamingFileLineAndWhatWasExpected(String text, int line, String expected)
            throws IOException {
        Path file = folder.resolve("bad.situation");
        Files.writeString(file, text, StandardCharsets.UTF_8);

        SituationFormatException e = assertThrows(SituationFormatException.class, () -> SituationFile.read(file));

        assertEquals(line, e.line(), e.getMessage());
        assertTrue(e.getMessage().startsWith(file + (line > 0 ? ":" + line + ": " : ": ")), e.getMessage());
        assertTrue(e.getMessage().contains(expected), e.getMessage());
    }

    @Test
    void aBinaryFileIsRefusedAsNotText() throws IOException {
        Path file = folder.resolve("image.png");
        Files.write(file, new byte[] {(byte) 0x89, 'P', 'N', 'G', (byte) 0xff, (byte) 0xfe, 0});

        SituationFormatException e = assertThrows(SituationFormatException.class, () -> SituationFile.read(file));
        assertTrue(e.getMessage().contains("not UTF-8 text"), e.getMessage());
    }

    private List<Path> listFolder() throws IOException {
        try (Stream<Path> files = Files.list(folder)) {
            return new ArrayList<>(files.toList());
        }
    }
}
