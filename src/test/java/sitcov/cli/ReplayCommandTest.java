package sitcov.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.function.UnaryOperator;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import sitcov.builtin.BuiltinRuns;
import sitcov.judge.Simulator;
import sitcov.oracle.Outcome;
import sitcov.oracle.RunResult;
import sitcov.render.GifFile;
import sitcov.results.ResultsFolder;
import sitcov.results.SignedEdits;
import sitcov.world.MapGenerator;

class ReplayCommandTest {
    /** The number (1 = first under the header) of the first row of the tiny reference run whose fault was FOUND. */
    private static int firstFoundRow() throws Exception {
        List<String> rows = Files.readAllLines(ResultsFolders.tinyReference().resolve(ResultsFolder.RUNS));
        for (int i = 1; i < rows.size(); i++) {
            if (rows.get(i).contains(",FOUND,")) {
                return i;
            }
        }
        throw new AssertionError("the tiny run found no fault");
    }

    @Test
    void aRowOfAResultsFolderReplaysExactlyAndIsDrawnBesideItsFaultFreeTwin(@TempDir Path dir) throws Exception {
        Path png = dir.resolve("row.png");
        Path gif = dir.resolve("row.gif");
        CliRunner r = CliRunner.run("replay", ResultsFolders.tinyReference().toString(), "--row",
                Integer.toString(firstFoundRow()), "--png", png.toString(), "--gif", gif.toString());
        assertEquals(0, r.exitCode(), r.err());
        assertTrue(r.out().contains("replays exactly") && r.out().contains("Verdict: FOUND"), r.out());
        // the faulty run's own outcome, as the row records it (outcome and ticks columns), not its twin's
        String[] cells = Files.readAllLines(ResultsFolders.tinyReference().resolve(ResultsFolder.RUNS))
                .get(firstFoundRow()).split(",", -1);
        long lastTick = Long.parseLong(cells[13]) - 1;
        String outcome = switch (cells[12]) {
            case "TARGET_REACHED" -> "Reached the Target at t=" + lastTick;
            case "TIMEOUT" -> "TIMEOUT at t=" + lastTick;
            default -> "Stopped at t=" + lastTick;
        };
        assertTrue(r.out().contains("With fault " + cells[11] + " (") && line(r.out(), "With fault").contains(outcome),
                r.out());
        assertTrue(r.out().contains("Without the fault (its twin"), r.out());
        BufferedImage image = ImageIO.read(png.toFile());
        assertTrue(image.getWidth() > 2 * image.getHeight(), "two maps side by side: " + image.getWidth() + "x" + image.getHeight());
        GifFile animation = GifFile.read(gif, 0, -1);
        assertTrue(animation.frames() >= 2, animation.frames() + " frames");
        BufferedImage first = animation.shown().get(0);
        BufferedImage last = animation.shown().get(1);
        assertTrue(first.getWidth() > 2 * first.getHeight(), "both runs side by side in the animation");
        int moved = 0;
        for (int y = 0; y < first.getHeight(); y += 2) {
            for (int x = 0; x < first.getWidth(); x += 2) {
                moved += first.getRGB(x, y) != last.getRGB(x, y) ? 1 : 0;
            }
        }
        assertTrue(moved > 20, "the cars moved between the first and the last frame: " + moved + " pixels differ");
    }

    @Test
    void aRowThatDoesNotReplayAsRecordedFailsSayingSo(@TempDir Path dir) throws Exception {
        Path copy = dir.resolve("tampered");
        ResultsFolders.copy(ResultsFolders.tinyReference(), copy);
        int row = firstFoundRow();
        List<String> rows = Files.readAllLines(copy.resolve(ResultsFolder.RUNS));
        // the fault-free row of the same map: its ticks column (14th) recorded one tick more than it ran
        int faultFreeRow = row - 1;
        while (!rows.get(faultFreeRow).contains(",NONE,")) {
            faultFreeRow--;
        }
        UnaryOperator<String> oneTickMore = line -> {
            String[] cells = line.split(",", -1);
            cells[13] = Long.toString(Long.parseLong(cells[13]) + 1);
            return String.join(",", cells);
        };
        // edited by hand, the row no longer matches its check: refused before anything is judged
        List<String> edited = new ArrayList<>(rows);
        edited.set(faultFreeRow, oneTickMore.apply(rows.get(faultFreeRow)));
        Files.write(copy.resolve(ResultsFolder.RUNS), edited);
        CliRunner hand = CliRunner.run("replay", copy.toString(), "--row", Integer.toString(row), "--png",
                dir.resolve("x.png").toString());
        assertEquals(ExitCode.USAGE, hand.exitCode(), hand.out());
        assertTrue(hand.err().contains("runs.csv:" + (faultFreeRow + 1) + ": this row was changed"), hand.err());

        // as another build of sitcov would have written it, checks and all: replay's own check finds it
        Files.write(copy.resolve(ResultsFolder.RUNS), rows);
        SignedEdits.editRunsRow(copy, faultFreeRow + 1, oneTickMore);
        CliRunner r = CliRunner.run("replay", copy.toString(), "--row", Integer.toString(row), "--png",
                dir.resolve("x.png").toString());
        assertEquals(ExitCode.FAILURE, r.exitCode(), r.out());
        assertTrue(r.err().contains("row " + row + " does not replay: the fault-free run was recorded as"), r.err());
        assertFalse(Files.exists(dir.resolve("x.png")), "nothing drawn for a row that does not replay");
    }

    @Test
    void aMapAndSeedsReplayWithoutAFolder(@TempDir Path dir) throws Exception {
        Path png = dir.resolve("seeds.png");
        CliRunner r = CliRunner.run("replay", "--seed", "1", "--fault", "17", "--png", png.toString());
        assertEquals(0, r.exitCode(), r.err());
        assertTrue(Files.size(png) > 0);
        // seed 1 reaches its Target without faults; fault 17 leaves the car standing until its time is up
        RunResult twin = BuiltinRuns.run(MapGenerator.generate(1), 1);
        assertEquals(Outcome.TARGET_REACHED, twin.outcome());
        assertTrue(line(r.out(), "Without the fault").endsWith("Reached the Target at t=" + (twin.ticks() - 1)), r.out());
        assertTrue(line(r.out(), "With fault 17").contains("TIMEOUT at t=4999"), r.out());
        assertTrue(line(r.out(), "With fault 17").contains("Verdict: FOUND by TIMEOUT"), r.out());
    }

    @Test
    void aRowOutsideTheFileOrAMissingFaultIsAUsageError() throws Exception {
        CliRunner row = CliRunner.run("replay", ResultsFolders.tinyReference().toString(), "--row", "100000");
        assertEquals(ExitCode.USAGE, row.exitCode());
        assertTrue(row.err().contains("has rows 1.."), row.err());
        CliRunner fault = CliRunner.run("replay", "--seed", "1");
        assertEquals(ExitCode.USAGE, fault.exitCode());
        assertTrue(fault.err().contains("--fault names one fault"), fault.err());
    }

    @Test
    void thePictureAndTheAnimationMayNotBeOneFileHoweverTheyAreSpelt(@TempDir Path dir) throws Exception {
        CliRunner same = CliRunner.run("replay", "--seed", "1", "--fault", "17", "--png", dir.resolve("f").toString(),
                "--gif", dir.resolve("f").toString());
        assertEquals(ExitCode.USAGE, same.exitCode());
        assertTrue(same.err().contains("--png and --gif both name"), same.err());
        Path link = Files.createSymbolicLink(dir.resolve("link.gif"), dir.resolve("replay.png"));
        CliRunner linked = CliRunner.run("replay", "--seed", "1", "--fault", "17", "--png", dir.resolve("replay.png").toString(),
                "--gif", link.toString());
        assertEquals(ExitCode.USAGE, linked.exitCode());
        assertTrue(linked.err().contains("--png " + dir.resolve("replay.png") + " and --gif " + link + " are the same file"),
                linked.err());
        assertFalse(Files.exists(dir.resolve("f")) || Files.exists(dir.resolve("replay.png")), "nothing written");
    }

    /** The line of {@code out} that starts with {@code start}. */
    private static String line(String out, String start) {
        return out.lines().filter(l -> l.startsWith(start)).findFirst().orElse("");
    }

    @Test
    void aRecordingPutInAnotherRunsPlaceIsRefusedNamingIt(@TempDir Path dir) throws Exception {
        Path copy = dir.resolve("swapped");
        ResultsFolders.copy(ResultsFolders.tinyReference(), copy);
        List<sitcov.results.ResultsRows.Row> recorded = new ArrayList<>();
        for (sitcov.results.ResultsRows.Row row : sitcov.results.ResultsRows.all(copy)) {
            if (row.variant().isPresent() && sitcov.recording.FolderRecordings.has(copy, row)) {
                recorded.add(row);
            }
        }
        assertTrue(recorded.size() >= 2, "the tiny run finds faults on more than one map: " + recorded.size());
        Path mine = sitcov.recording.FolderRecordings.file(copy, sitcov.recording.FolderRecordings.key(recorded.get(0), false));
        Path other = sitcov.recording.FolderRecordings.file(copy, sitcov.recording.FolderRecordings.key(recorded.get(1), false));
        Files.copy(other, mine, java.nio.file.StandardCopyOption.REPLACE_EXISTING);
        CliRunner r = CliRunner.run("replay", copy.toString(), "--row", Integer.toString(recorded.get(0).number()), "--png",
                dir.resolve("x.png").toString());
        assertEquals(ExitCode.FAILURE, r.exitCode(), r.out());
        assertTrue(r.err().contains(mine.toString()) && r.err().contains("is of another run"), r.err());
        assertFalse(Files.exists(dir.resolve("x.png")), "nothing drawn");
    }
}
