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
}
