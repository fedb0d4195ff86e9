package sitcov.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashSet;
import java.util.Set;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import sitcov.coverage.GridDefinition;
import sitcov.world.MapGenerator;

class CoverageCommandTest {
    @TempDir
    Path dir;

    @Test
    void coveragePrintsTheCellsTheMapsReachAndDrawsTheHeatMap() throws Exception {
        Path png = dir.resolve("grid.png");
        CliRunner r = CliRunner.run("coverage", "--maps", "60", "--seed", "5", "--png", png.toString());
        assertEquals(0, r.exitCode(), r.err());
        GridDefinition grid = GridDefinition.paper();
        Set<Integer> cells = new HashSet<>();
        for (long s = 5; s < 65; s++) {
            cells.add(grid.cellOf(grid.values(MapGenerator.layout(s))));
        }
        assertTrue(r.out().contains("cells covered   " + cells.size() + " of 216"), r.out());
        assertTrue(ImageIO.read(png.toFile()).getWidth() > 500);
    }

    @Test
    void aMalformedGridFileIsRefusedWithItsLineAndExitCode2() throws Exception {
        Path bad = dir.resolve("bad.txt");
        Files.writeString(bad, "sitcov-grid 1\ncriterion start-target 10 5\n");
        CliRunner r = CliRunner.run("coverage", "--maps", "3", "--grid", bad.toString());
        assertEquals(2, r.exitCode());
        assertTrue(r.err().contains("bad.txt:2:"), r.err());
    }
}
