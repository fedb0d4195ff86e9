package sitcov.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class PrintedCommandsTest {
    @Test
    void everyCommandABuiltinFolderPrintsRunsAsPrinted(@TempDir Path dir) throws Exception {
        Path folder = ResultsFolders.tinyReference();
        List<List<String>> printed = PrintedCommands.of(folder, dir);
        assertFalse(printed.isEmpty(), "the report prints the replay of each fault's first finding");
        for (List<String> command : printed) {
            CliRunner run = CliRunner.run(command.toArray(String[]::new));
            assertEquals(ExitCode.OK, run.exitCode(), "printed: " + command + "\n" + run.err());
        }
    }

    @Test
    void theReproduceLineAndTheSeedsHintsOfSimulateNameTheController() {
        CliRunner r = CliRunner.run("simulate", "--maps", "12", "--summary", "--controller", "builtin:16");
        assertEquals(ExitCode.OK, r.exitCode(), r.err());
        String prefix = "Reproduce: " + Main.LAUNCHER + " ";
        String reproduce = r.out().lines().filter(l -> l.startsWith(prefix)).findFirst().orElseThrow();
        List<String> args = PrintedCommands.shellWords(reproduce.substring(prefix.length()));
        assertEquals(List.of("simulate", "--maps", "12", "--seed", "1", "--summary", "--controller", "builtin:16"), args);
        CliRunner again = CliRunner.run(args.toArray(String[]::new));
        assertEquals(r.out(), again.out(), "the printed command gives the same table");
        List<String> hints = r.out().lines().filter(l -> l.contains("see one with:")).toList();
        assertFalse(hints.isEmpty(), "the planted fault has accidents on these maps: " + r.out());
        hints.forEach(h -> assertTrue(h.endsWith("see one with: simulate --seed S --controller 'builtin:16' --png run.png"),
                h));
    }

    @Test
    void aControllerQuotedForTheShellComesBackWhole() {
        assertEquals(List.of("simulate", "--controller", "exec:python3 it's.py", "x"),
                PrintedCommands.shellWords("simulate --controller " + Calibration.shellQuoted("exec:python3 it's.py") + " x"));
        assertEquals(List.of("a", "b c"), PrintedCommands.shellWords("a  \"b c\""));
    }
}
