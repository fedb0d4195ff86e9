package sitcov.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashSet;
import java.util.List;
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

    @Test
    void aGridEdgeThatIsNotANumberIsNamedWithTheFix() throws Exception {
        Path bad = dir.resolve("words.txt");
        Files.writeString(bad, "sitcov-grid 1\ncriterion start-target 0 forty inf\n");
        CliRunner r = CliRunner.run("coverage", "--maps", "3", "--grid", bad.toString());
        assertEquals(2, r.exitCode());
        assertTrue(r.err().contains("words.txt:2: criterion start-target: the edge 'forty' is not a number; edges are"
                + " metres written as numbers such as 0 40 80.5, or inf for an open top"), r.err());
        assertFalse(r.err().contains("For input string"), r.err());
    }

    @Test
    void progressGoesToErrWhileTheMapsAreCounted() {
        CliRunner r = CliRunner.run("coverage", "--maps", "2000");
        assertEquals(0, r.exitCode(), r.err());
        // told every thousand maps off a console, each at a new tenth: 1000 (50 %) and 2000 (100 %)
        assertEquals(List.of("coverage: 1000/2000 (50%)", "coverage: 2000/2000 (100%)"),
                r.err().lines().map(l -> l.substring(0, l.indexOf(')') + 1)).toList(), r.err());
        assertFalse(r.out().contains("coverage: "), "progress stays off stdout");
    }

    @Test
    void aPngThatCannotBeWrittenIsNamedWithItsCause() {
        assumeTrue(Files.exists(Path.of("/dev/full")), "a device that is always full");
        CliRunner r = CliRunner.run("coverage", "--maps", "3", "--png", "/dev/full");
        assertEquals(1, r.exitCode());
        assertTrue(r.err().contains("sitcov: coverage: could not write --png /dev/full: no space left on device."), r.err());
    }
}
