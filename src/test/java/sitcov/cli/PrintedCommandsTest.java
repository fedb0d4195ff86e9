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

    /** Breaks the check of the first row of {@code runs} (its ticks one more), as a hand edit does. */
    private static void editByHand(Path runs) throws Exception {
        List<String> lines = new java.util.ArrayList<>(Files.readAllLines(runs));
        String[] cells = lines.get(1).split(",", -1);
        cells[13] = Long.toString(Long.parseLong(cells[13]) + 1);
        lines.set(1, String.join(",", cells));
        Files.write(runs, lines);
    }

    @Test
    void theAdviceOfAFolderRefusedForAnEditRunsAsPrintedThoughItsPresetLiesOutsideExperiments(@TempDir Path dir)
            throws Exception {
        Path reference = ResultsFolders.tinyReference();
        assertFalse(Files.exists(Path.of("experiments", "tiny.properties")), "the tiny preset is not in experiments/");
        Path edited = dir.resolve("edited");
        ResultsFolders.copy(reference, edited);
        editByHand(edited.resolve("runs.csv"));
        CliRunner refused = CliRunner.run("report", edited.toString());
        assertEquals(ExitCode.USAGE, refused.exitCode(), refused.err());
        List<String> advice = new java.util.ArrayList<>(PrintedCommands.advised(refused.err(), "into a new folder: "));
        assertEquals(List.of("run", "--again", edited.toString()), advice);
        // its new folder goes to the scratch folder, as every printed command's output does here
        advice.addAll(List.of("--out", dir.resolve("again").toString()));
        CliRunner again = CliRunner.run(advice.toArray(String[]::new));
        assertEquals(ExitCode.OK, again.exitCode(), again.err());
        ResultsFolders.assertSameResults(reference, dir.resolve("again"));
    }

    @Test
    void theAdviceOfACampaignsRefusedSubFolderRunsTheCampaignAgainAsPrinted(@TempDir Path dir) throws Exception {
        Path reference = CampaignRunTest.reference();
        Path edited = dir.resolve("campaign");
        ResultsFolders.copy(reference, edited);
        editByHand(edited.resolve("fault-17").resolve("runs.csv"));
        for (List<String> command : List.of(List.of("report", edited.toString()),
                List.of("replay", edited.resolve("fault-17").toString(), "--row", "1", "--png", dir.resolve("r.png").toString()))) {
            CliRunner refused = CliRunner.run(command.toArray(String[]::new));
            assertEquals(ExitCode.USAGE, refused.exitCode(), refused.err());
            assertTrue(refused.err().contains(edited.resolve("fault-17").resolve("runs.csv") + ":2: this row was changed"),
                    refused.err());
            assertEquals(List.of("run", "--again", edited.toString()),
                    PrintedCommands.advised(refused.err(), "into a new folder: "), command + " advises the campaign");
        }
        List<String> advice = new java.util.ArrayList<>(PrintedCommands.advised(
                CliRunner.run("report", edited.toString()).err(), "into a new folder: "));
        advice.addAll(List.of("--out", dir.resolve("again").toString(), "--threads", "2"));
        CliRunner again = CliRunner.run(advice.toArray(String[]::new));
        assertEquals(ExitCode.OK, again.exitCode(), again.err());
        CampaignRunTest.assertSame(reference, dir.resolve("again"));
    }

    @Test
    void theReproduceLineOfAControllerProgramKeepsItQuotedAndReproducesTheTable() {
        String controller = "exec:python3 experiments/controllers/minimal.py";
        CliRunner r = CliRunner.run("simulate", "--maps", "2", "--summary", "--controller", controller);
        assertEquals(ExitCode.OK, r.exitCode(), r.err());
        String prefix = "Reproduce: " + Main.LAUNCHER + " ";
        String reproduce = r.out().lines().filter(l -> l.startsWith(prefix)).findFirst().orElseThrow();
        List<String> args = PrintedCommands.shellWords(reproduce.substring(prefix.length()));
        assertEquals(List.of("simulate", "--maps", "2", "--seed", "1", "--summary", "--controller", controller), args);
        CliRunner again = CliRunner.run(args.toArray(String[]::new));
        assertEquals(ExitCode.OK, again.exitCode(), again.err());
        assertEquals(r.out(), again.out(), "the printed command gives the same table");
        assertTrue(r.out().contains("TIMEOUT"), "the table counts the runs' outcomes: " + r.out());
    }

    @Test
    void aControllerQuotedForTheShellComesBackWhole() {
        assertEquals(List.of("simulate", "--controller", "exec:python3 it's.py", "x"),
                PrintedCommands.shellWords("simulate --controller " + Calibration.shellQuoted("exec:python3 it's.py") + " x"));
        assertEquals(List.of("a", "b c"), PrintedCommands.shellWords("a  \"b c\""));
    }
}
