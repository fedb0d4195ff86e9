package sitcov.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;

class BenchCommandTest {

    @Test
    void aTinyBenchPrintsTicksRunsCandidateMapsPerSecondAndSecondsPerJudgedMap() {
        CliRunner result = CliRunner.run("bench", "--maps", "1", "--candidates", "200", "--judged", "2");

        assertEquals(ExitCode.OK, result.exitCode(), result.err());
        for (String measure : new String[] {"simulated ticks per second", "microseconds per tick", "runs per second",
                "candidate maps per second", "seconds for 20000 candidates", "seconds a judged map, until verdict",
                "seconds a judged map, to the end"}) {
            assertTrue(figure(result.out(), measure) > 0, measure);
        }
        assertTrue(result.out().contains("<= 8 with 15 moving cars"), result.out());
        assertTrue(result.out().contains("Judged maps: 1..2, each run fault-free and once per PAPER fault"), result.out());
    }

    @Test
    void aBadCountIsRefusedWithTheFix() {
        CliRunner result = CliRunner.run("bench", "--candidates", "none");

        assertEquals(ExitCode.USAGE, result.exitCode());
        assertTrue(result.err().startsWith("sitcov: bench: --candidates needs a whole number from 1 to 10000000"),
                result.err());
    }

    /** The number printed after {@code measure} on its line of the table. */
    private static double figure(String out, String measure) {
        Matcher m = Pattern.compile("(?m)^\\s*" + Pattern.quote(measure) + "\\s+([0-9][0-9.]*)\\b").matcher(out);
        assertTrue(m.find(), measure + " missing from:\n" + out);
        return Double.parseDouble(m.group(1));
    }
}
