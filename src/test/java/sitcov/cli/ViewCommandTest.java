package sitcov.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.awt.GraphicsEnvironment;
import org.junit.jupiter.api.Test;

class ViewCommandTest {
    @Test
    void withoutADisplayTheViewerSaysWhereToRunItInsteadOfFailing() {
        // the tests run headless (the pom sets java.awt.headless); the painting is tested in sitcov.viewer
        assumeTrue(GraphicsEnvironment.isHeadless());
        CliRunner r = CliRunner.run("view", "--seed", "1");
        assertEquals(ExitCode.USAGE, r.exitCode());
        assertTrue(r.err().contains("xvfb-run") && r.err().contains("replay"), r.err());
    }

    @Test
    void aViewNeedsAMap() {
        CliRunner r = CliRunner.run("view");
        assertEquals(ExitCode.USAGE, r.exitCode());
        assertTrue(r.err().contains("give --seed S"), r.err());
    }

    @Test
    void withPngTheViewersPanesAtATickArePaintedIntoAPictureWithoutAWindow(@org.junit.jupiter.api.io.TempDir
                                                                           java.nio.file.Path dir) throws Exception {
        java.nio.file.Path png = dir.resolve("view.png");
        CliRunner r = CliRunner.run("view", "--seed", "1", "--faults", "17", "--png", png.toString(), "--tick", "150");
        assertEquals(ExitCode.OK, r.exitCode(), r.err());
        assertTrue(r.out().contains("painted at tick 150 and 150 into"), r.out());
        var image = javax.imageio.ImageIO.read(png.toFile());
        java.awt.Dimension map = sitcov.render.MapRenderer.imageSize(sitcov.render.MapRenderer.DEFAULT_SCALE);
        assertEquals(2 * map.width + 8, image.getWidth(), "two panes, the twin and the faulty run, 8 pixels apart");
        assertTrue(image.getHeight() > map.height, "each pane's header over its map");
        CliRunner noPng = CliRunner.run("view", "--seed", "1", "--tick", "150");
        assertEquals(ExitCode.USAGE, noPng.exitCode());
        assertTrue(noPng.err().contains("add --png FILE"), noPng.err());
    }
}
