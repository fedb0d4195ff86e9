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
import javax.imageio.ImageReader;
import javax.imageio.stream.ImageInputStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import sitcov.report.ResultsFolder;
import sitcov.report.SignedEdits;

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
        assertTrue(r.out().contains("replays exactly") && r.out().contains(": FOUND"), r.out());
        BufferedImage image = ImageIO.read(png.toFile());
        assertTrue(image.getWidth() > 2 * image.getHeight(), "two maps side by side: " + image.getWidth() + "x" + image.getHeight());
        ImageReader reader = ImageIO.getImageReadersByFormatName("gif").next();
        try (ImageInputStream in = ImageIO.createImageInputStream(gif.toFile())) {
            reader.setInput(in);
            int frames = reader.getNumImages(true);
            assertTrue(frames >= 2, frames + " frames");
            BufferedImage first = reader.read(0);
            BufferedImage last = reader.read(frames - 1);
            assertTrue(first.getWidth() > 2 * first.getHeight(), "both runs side by side in the animation");
            int moved = 0;
            for (int y = 0; y < first.getHeight(); y += 2) {
                for (int x = 0; x < first.getWidth(); x += 2) {
                    moved += first.getRGB(x, y) != last.getRGB(x, y) ? 1 : 0;
                }
            }
            assertTrue(moved > 20, "the cars moved between the first and the last frame: " + moved + " pixels differ");
        } finally {
            reader.dispose();
        }
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
}
