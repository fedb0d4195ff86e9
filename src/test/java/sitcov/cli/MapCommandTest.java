package sitcov.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import sitcov.world.MapGenerator;
import sitcov.world.SituationFile;

class MapCommandTest {
    @TempDir
    Path folder;

    @Test
    void aSeedIsDescribedInOneParagraph() {
        CliRunner result = CliRunner.run("map", "--seed", "5");

        assertEquals(ExitCode.OK, result.exitCode(), result.err());
        assertTrue(result.out().startsWith("Map of seed 5: "), result.out());
        assertEquals(1, result.out().lines().count());
    }

    @Test
    void aSavedMapLoadsBackAsTheSameMapAndDrawsToPng() throws Exception {
        Path situation = folder.resolve("five.situation");
        Path png = folder.resolve("five.png");

        CliRunner saved = CliRunner.run("map", "--seed", "5", "--save", situation.toString());
        CliRunner loaded = CliRunner.run("map", "--load", situation.toString(), "--png", png.toString());

        assertEquals(ExitCode.OK, saved.exitCode(), saved.err());
        assertEquals(ExitCode.OK, loaded.exitCode(), loaded.err());
        assertEquals(MapGenerator.generate(5), SituationFile.read(situation));
        assertEquals(saved.out().lines().findFirst(), loaded.out().lines().findFirst());
        assertTrue(Files.size(png) > 1000);
    }

    @Test
    void aBadSeedIsRefusedWithTheFix() {
        CliRunner result = CliRunner.run("map", "--seed", "forty-two");

        assertEquals(ExitCode.USAGE, result.exitCode());
        assertTrue(result.err().startsWith("sitcov: map: --seed needs a whole number such as 42"), result.err());
    }

    @Test
    void seedAndLoadTogetherOrNeitherAreRefused() {
        assertEquals(ExitCode.USAGE, CliRunner.run("map").exitCode());
        assertEquals(ExitCode.USAGE, CliRunner.run("map", "--seed", "1", "--load", "x").exitCode());
    }

    @Test
    void aMissingSituationFileIsNamed() {
        CliRunner result = CliRunner.run("map", "--load", folder.resolve("nope.situation").toString());

        assertEquals(ExitCode.USAGE, result.exitCode());
        assertTrue(result.err().contains("nope.situation (no such file)"), result.err());
    }

    @Test
    void aMalformedSituationFileIsReportedWithItsLineAndLeftAlone() throws IOException {
        Path bad = folder.resolve("bad.situation");
        Files.writeString(bad, "sitcov-situation 1\nseed x\n");

        CliRunner result = CliRunner.run("map", "--load", bad.toString());

        assertEquals(ExitCode.USAGE, result.exitCode());
        assertTrue(result.err().contains("bad.situation:2: expected a whole number for SEED"), result.err());
        assertEquals("sitcov-situation 1\nseed x\n", Files.readString(bad));
    }

    @Test
    void aTargetNamingARoadItDoesNotStandOnIsRefusedByMapAndSimulateNamingTheFix() throws IOException {
        sitcov.world.Target target = MapGenerator.generate(5).layout().target().orElseThrow();
        int wrong = target.roadId() == 0 ? 1 : 0;
        String text = SituationFile.format(MapGenerator.generate(5)).replace("\ntarget " + target.position().x() + " "
                + target.position().y() + " " + target.roadId() + "\n", "\ntarget " + target.position().x() + " "
                + target.position().y() + " " + wrong + "\n");
        Path edited = folder.resolve("edited.situation");
        Files.writeString(edited, text);

        for (String command : new String[] {"map", "simulate"}) {
            CliRunner result = CliRunner.run(command, "--load", edited.toString());

            assertEquals(ExitCode.USAGE, result.exitCode(), result.err());
            assertTrue(result.err().contains("edited.situation:") && result.err().contains("names road " + wrong
                    + " but stands on road " + target.roadId() + ": set its ROAD_ID to " + target.roadId()), result.err());
            assertFalse(result.err().contains("\tat "), result.err());
        }
        assertEquals(text, Files.readString(edited));
    }

    @Test
    void anOutputInAMissingFolderIsRefusedBeforeAnythingIsWritten() {
        Path png = folder.resolve("no-such-folder").resolve("map.png");

        CliRunner result = CliRunner.run("map", "--seed", "1", "--png", png.toString());

        assertEquals(ExitCode.USAGE, result.exitCode());
        assertTrue(result.err().contains("does not exist; create it first"), result.err());
        assertEquals("", result.out());
        assertFalse(Files.exists(png));
    }

    @Test
    void anUnknownOptionListsTheValidOnes() {
        CliRunner result = CliRunner.run("map", "--sed", "1");

        assertEquals(ExitCode.USAGE, result.exitCode());
        assertTrue(result.err().contains("unknown option '--sed'; the options are"), result.err());
    }

    @Test
    void checkSaysWhichSituationFilesAreValidAndWhyTheOthersAreRefused() throws Exception {
        Path good = folder.resolve("good.situation");
        Path noTarget = folder.resolve("no-target.situation");
        Path bad = folder.resolve("bad.situation");
        String text = sitcov.world.SituationFile.format(sitcov.world.MapGenerator.generate(1));
        Files.writeString(good, text);
        Files.writeString(noTarget, text.replaceAll("(?m)^target .*\n", ""));
        Files.writeString(bad, text.replace("road 0 NORTH_SOUTH 190.485 49.336 100.0", "road 0 NORTH_SOUTH 190.485 49.336 300.0"));
        CliRunner r = CliRunner.run("map", "--check", good.toString(), noTarget.toString(), bad.toString());
        assertEquals(ExitCode.USAGE, r.exitCode());
        assertTrue(r.out().contains(good + ": ok (6 roads"), r.out());
        assertTrue(r.out().contains(noTarget + ": ok") && r.out().contains("no Target or car start, so it cannot be run"), r.out());
        assertTrue(r.err().contains(bad + ":6: breaks a rule of the world: road 0 leaves"), r.err());
        assertTrue(r.out().contains("2 of 3 situation files are valid; 1 refused"), r.out());
        assertEquals(0, CliRunner.run("map", "--check", good.toString()).exitCode());
    }

    @Test
    void theSameFileForTwoOutputsIsRefused() {
        Path same = folder.resolve("same");
        CliRunner r = CliRunner.run("map", "--seed", "3", "--png", same.toString(), "--save", same.toString());
        assertEquals(ExitCode.USAGE, r.exitCode());
        assertTrue(r.err().contains("--png and --save both name"), r.err());
        assertTrue(!Files.exists(same));
    }

    @Test
    void aFullDiskIsNamedWithTheFileItStopped() throws Exception {
        assumeTrue(Files.exists(Path.of("/dev/full")), "a device that is always full");
        Path png = folder.resolve("map.png");
        CliRunner save = CliRunner.run("map", "--seed", "5", "--save", "/dev/full", "--png", png.toString());
        assertEquals(1, save.exitCode());
        assertTrue(save.err().contains("sitcov: map: could not write --save /dev/full: no space left on device."),
                save.err());
        assertFalse(Files.exists(png), "it stopped at the first file it could not write");
        CliRunner drawn = CliRunner.run("map", "--seed", "5", "--png", "/dev/full");
        assertEquals(1, drawn.exitCode());
        assertTrue(drawn.err().contains("sitcov: map: could not write --png /dev/full: no space left on device."),
                drawn.err());
        assertFalse(drawn.err().contains("I/O error writing PNG file!"), drawn.err());
    }

    @Test
    void aPictureMayNotBeWrittenOverTheSituationItIsDrawnFrom() throws Exception {
        Path situation = folder.resolve("read.situation");
        assertEquals(0, CliRunner.run("map", "--seed", "3", "--save", situation.toString()).exitCode());
        String before = Files.readString(situation);
        Path link = Files.createSymbolicLink(folder.resolve("picture.png"), situation);
        CliRunner r = CliRunner.run("map", "--load", situation.toString(), "--png", link.toString());
        assertEquals(ExitCode.USAGE, r.exitCode());
        assertTrue(r.err().contains("--load " + situation + " and --png " + link + " are the same file"), r.err());
        assertEquals(before, Files.readString(situation), "the situation file is untouched");
    }
}
