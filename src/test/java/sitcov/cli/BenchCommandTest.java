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
                "seconds a judged map, to the end", "seconds a judged map, ALL, forked", "seconds a judged map, ALL, whole",
                "ticks a judged map, ALL, forked"}) {
            assertTrue(figure(result.out(), measure) > 0, measure);
        }
        assertTrue(result.out().contains("<= 8 with 15 moving cars"), result.out());
        // maps 1 and 2 judged with all twenty faults: some faults never depart, so forked steps fewer ticks
        assertTrue(figure(result.out(), "ticks a judged map, ALL, forked")
                < Double.parseDouble(result.out().replaceAll("(?s).*against (\\d+) run whole.*", "$1")), result.out());
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

    @Test
    void comparingThisBuildWithItselfAlternatesBothKindsOfWorkAndPrintsTheirRatios() throws Exception {
        java.nio.file.Path own = java.nio.file.Path.of(BuildComparison.class.getProtectionDomain().getCodeSource()
                .getLocation().toURI());
        java.io.ByteArrayOutputStream out = new java.io.ByteArrayOutputStream();
        BuildComparison.of(own).run(3, 2, 1, new java.io.PrintStream(out, true, java.nio.charset.StandardCharsets.UTF_8),
                new java.io.PrintStream(java.io.OutputStream.nullOutputStream()));
        String printed = out.toString(java.nio.charset.StandardCharsets.UTF_8);
        assertTrue(printed.contains("3 alternated rounds"), printed);
        assertTrue(printed.contains("fault-free runs of maps 1..2:"), printed);
        assertTrue(printed.contains("maps 1..1 judged with the PAPER faults"), printed);
        Matcher ratio = Pattern.compile("this / other (\\d+\\.\\d+) \\(min (\\d+\\.\\d+), max (\\d+\\.\\d+)\\)")
                .matcher(printed);
        for (int kind = 0; kind < 2; kind++) {
            assertTrue(ratio.find(), printed);
            double median = Double.parseDouble(ratio.group(1));
            assertTrue(Double.parseDouble(ratio.group(2)) <= median && median <= Double.parseDouble(ratio.group(3)), printed);
        }
    }

    @Test
    void aComparisonWithSomethingThatIsNotABuildIsRefusedWithTheFix() {
        CliRunner missing = CliRunner.run("bench", "--vs", "no/such/build");
        assertEquals(2, missing.exitCode());
        assertTrue(missing.err().contains("--vs no/such/build does not exist; give another build's classes folder"), missing.err());
        CliRunner mixed = CliRunner.run("bench", "--vs", ".", "--maps", "3");
        assertEquals(2, mixed.exitCode());
        assertTrue(mixed.err().contains("leave out --maps"), mixed.err());
        CliRunner notABuild = CliRunner.run("bench", "--vs", "experiments");
        assertEquals(2, notABuild.exitCode());
        assertTrue(notABuild.err().contains("is not a sitcov build this bench can drive"), notABuild.err());
    }
}
