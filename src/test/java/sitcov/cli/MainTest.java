package sitcov.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class MainTest {

    @Test
    void helpListsEveryCommandAndExitsZero() {
        CliRunner result = CliRunner.run("--help");

        assertEquals(ExitCode.OK, result.exitCode());
        for (String command : new String[] {"run", "merge", "simulate", "map", "coverage", "faults", "bench"}) {
            assertTrue(result.out().contains("\n  " + command + " "), command + " missing from:\n" + result.out());
        }
        assertEquals("", result.err());
    }

    @Test
    void versionPrintsTheBuildVersion() {
        CliRunner result = CliRunner.run("--version");

        assertEquals(ExitCode.OK, result.exitCode());
        assertTrue(result.out().matches("sitcov \\d+\\.\\d+\\.\\d+(-SNAPSHOT)?\\R"), result.out());
    }

    @Test
    void anUnknownOptionIsOneLineWithTheUsageHintAndExitTwo() {
        CliRunner result = CliRunner.run("--frobnicate");

        assertEquals(ExitCode.USAGE, result.exitCode());
        assertEquals("", result.out());
        String[] lines = result.err().split("\\R");
        assertEquals(2, lines.length, result.err());
        assertTrue(lines[0].startsWith("sitcov: unknown option '--frobnicate'"), lines[0]);
        assertEquals("Run 'experiments/sitcov --help' for usage.", lines[1]);
    }

    @Test
    void anUnknownCommandNamesTheValidOnesAndExitsTwo() {
        CliRunner result = CliRunner.run("simulat");

        assertEquals(ExitCode.USAGE, result.exitCode());
        assertTrue(result.err().startsWith("sitcov: unknown command 'simulat'; the commands are run, merge, report, replay, export, view, simulate,"),
                result.err());
    }

    @Test
    void helpListsOnlyCommandsThatAreBuilt() {
        CliRunner help = CliRunner.run("--help");
        assertTrue(help.out().contains("replay") && help.out().contains("report") && !help.out().contains("not available"),
                help.out());
        CliRunner result = CliRunner.run("replay");
        assertEquals(ExitCode.USAGE, result.exitCode());
        assertTrue(result.err().contains("give a results folder and a row, or --seed S, or --load FILE"), result.err());
    }

    @Test
    void commandHelpShowsTheCommandsSynopsis() {
        CliRunner result = CliRunner.run("map", "--help");

        assertEquals(ExitCode.OK, result.exitCode());
        assertTrue(result.out().startsWith("Usage: experiments/sitcov map --seed S"), result.out());
    }
}
