package sitcov.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** A situation file is checked against the rules the generator's maps keep, not only its syntax. */
class SituationValidationTest {
    private static final String SEED_1 = SituationFile.format(MapGenerator.generate(1));

    @TempDir
    Path folder;

    private static List<String> lines() {
        return new ArrayList<>(SEED_1.lines().toList());
    }

    private static int lineOf(List<String> lines, String start) {
        for (int i = 0; i < lines.size(); i++) {
            if (lines.get(i).startsWith(start)) {
                return i;
            }
        }
        throw new IllegalArgumentException("no line starting '" + start + "'");
    }

    private static SituationFormatException refused(List<String> lines) {
        return assertThrows(SituationFormatException.class, () -> SituationFile.parse(lines, "edited.situation"));
    }

    @Test
    void aParkedCarMovedIntoAJunctionIsRefusedAtItsLine() {
        List<String> lines = lines();
        int at = lineOf(lines, "parked-car 0 ");
        String[] w = lines.get(at).split(" ");
        Junction j = MapGenerator.generate(1).layout().junctions().get(0);
        lines.set(at, "parked-car 0 " + w[2] + " " + j.centre().x() + " " + j.centre().y() + " " + w[5]);
        SituationFormatException e = refused(lines);
        assertEquals(at + 1, e.line(), e.getMessage());
        assertTrue(e.getMessage().contains("breaks a rule of the world: parked car 0 "), e.getMessage());
    }

    @Test
    void aRoadOffTheWorldIsRefusedAtItsLine() {
        List<String> lines = lines();
        int at = lineOf(lines, "road 0 ");
        lines.set(at, lines.get(at).replace(" 100.0", " 260.0"));
        SituationFormatException e = refused(lines);
        assertEquals(at + 1, e.line(), e.getMessage());
        assertTrue(e.getMessage().contains("road 0 leaves the 200.0 x 100.0 m world"), e.getMessage());
    }

    @Test
    void theCarStartingOffTheRoadIsRefusedAtItsLine() {
        List<String> lines = lines();
        int at = lineOf(lines, "car-start ");
        lines.set(at, "car-start 20.0 20.0 WEST");
        SituationFormatException e = refused(lines);
        assertEquals(at + 1, e.line());
        assertTrue(e.getMessage().contains("the autonomous car does not start on a lane centre"), e.getMessage());
    }

    @Test
    void coordinatesFarOutsideTheWorldAndFloodsOfCarsAreRefusedNamingTheLimit() {
        List<String> far = lines();
        int at = lineOf(far, "target ");
        far.set(at, "target 1e308 5 3");
        assertTrue(refused(far).getMessage().contains("within 1000 m of the origin"));

        List<String> flood = lines();
        int car = lineOf(flood, "moving-car ");
        for (int i = 0; i < SituationFile.MAX_CARS; i++) {
            flood.add(car, flood.get(car));
        }
        SituationFormatException e = refused(flood);
        assertTrue(e.getMessage().contains("more than 200 moving cars: a situation holds at most 200"), e.getMessage());
        assertEquals(car + SituationFile.MAX_CARS + 1, e.line());
    }

    @Test
    void aByteOrderMarkIsAcceptedAndTheMapIsTheSame() throws Exception {
        Path file = folder.resolve("bom.situation");
        Files.writeString(file, "\uFEFF" + SEED_1, StandardCharsets.UTF_8);
        assertEquals(MapGenerator.generate(1), SituationFile.read(file));
    }

    @Test
    void bytesThatAreNotUtf8TextOrAFileTooLargeAreRefusedPlainly() throws Exception {
        Path binary = folder.resolve("binary.situation");
        Files.write(binary, new byte[] {(byte) 0xff, (byte) 0xfe, 0, 1});
        SituationFormatException e = assertThrows(SituationFormatException.class, () -> SituationFile.read(binary));
        assertTrue(e.getMessage().endsWith("not UTF-8 text (is this a situation file?)"), e.getMessage());

        Path huge = folder.resolve("huge.situation");
        Files.writeString(huge, SEED_1 + "#".repeat(SituationFile.MAX_BYTES));
        SituationFormatException big = assertThrows(SituationFormatException.class, () -> SituationFile.read(huge));
        assertTrue(big.getMessage().contains("larger than 1 MiB"), big.getMessage());
    }

    @Test
    void everyGeneratedMapPassesTheChecksOnLoad() throws Exception {
        for (long seed = 1; seed <= 200; seed++) {
            WorldMap map = MapGenerator.generate(seed * 104729);
            assertEquals(map, SituationFile.parse(SituationFile.format(map).lines().toList(), "seed " + seed));
        }
    }
}
