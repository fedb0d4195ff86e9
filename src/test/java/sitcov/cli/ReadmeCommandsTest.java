package sitcov.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.awt.GraphicsEnvironment;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Every command of a fenced block of the README runs as printed (src/README.md, "Checks on the documentation"),
 * in this JVM through {@link Main#run}, with what would take minutes cut down: {@code run} is checked with
 * {@code --dry-run} (the preset and every option read, nothing run), {@code --maps N} is cut to one map, files
 * are written into a temporary folder, and the results folder of {@code run smoke} is the tiny preset's. A line
 * marked {@code # needs a display} is run where there is none and must say so.
 */
class ReadmeCommandsTest {
    private static final Path README = Path.of("README.md");
    private static final String LAUNCHER = Main.LAUNCHER + " ";
    private static final Set<String> OUTPUTS = Set.of("--png", "--gif", "--save", "--trace", "--out");
    private static final Set<String> COUNTS = Set.of("--maps");
    private static final String SMOKE_FOLDER = "target/results/smoke-seed1";

    @TempDir
    Path dir;

    @Test
    void everyCommandOfTheReadmeRunsAsPrinted() throws IOException {
        List<String> commands = commands(Files.readString(README, StandardCharsets.UTF_8));
        assertTrue(commands.contains("mvn -q compile exec:java") && commands.contains("mvn -B test"),
                "the two commands are in README.md: " + commands);
        List<String> problems = new ArrayList<>();
        for (String line : commands) {
            String problem = check(line);
            if (problem != null) {
                problems.add(line + "\n    " + problem);
            }
        }
        assertEquals(List.of(), problems, "README commands that do not run as printed");
    }

    @Test
    void theMainJobIsTheCommandWithNoArguments() throws IOException {
        String pom = Files.readString(Path.of("pom.xml"), StandardCharsets.UTF_8);
        assertTrue(pom.contains("<main.class>sitcov.cli.Main</main.class>"), "exec:java runs Main");
        CliRunner help = CliRunner.run("--help");
        assertTrue(help.out().contains("With no command, runs the paper's comparison (run paper-rq1)"), help.out());
        String ci = Files.readString(Path.of(".ci", "run"), StandardCharsets.UTF_8);
        assertTrue(ci.lines().anyMatch(l -> l.equals("mvn -B test")), "CI runs the README's test command: " + ci);
    }

    @Test
    void theTwentyLineControllerShownIsTheOneShipped() throws IOException {
        String shipped = Files.readString(Path.of("experiments", "controllers", "minimal.py"), StandardCharsets.UTF_8);
        for (Path doc : List.of(README, Path.of("experiments", "controllers", "README.md"))) {
            String markdown = Files.readString(doc, StandardCharsets.UTF_8);
            int start = markdown.indexOf("```python\n");
            assertTrue(start >= 0, doc + " shows the controller");
            int from = start + "```python\n".length();
            assertEquals(shipped, markdown.substring(from, markdown.indexOf("```", from)), doc + " shows minimal.py as shipped");
        }
        assertTrue(shipped.lines().count() <= 20, "twenty lines at most");
    }

    /** Why a README line does not run as printed, or null when it does. */
    private String check(String line) throws IOException {
        String command = line.replaceFirst("\\s+#.*$", "");
        boolean needsDisplay = line.matches(".*#\\s*needs a display.*");
        if (command.equals("mvn -q compile exec:java")) {
            return expectOk(CliRunner.run("run", "paper-rq1", "--dry-run"));
        }
        if (command.equals("mvn -B test")) {
            return null; // this very run
        }
        if (!command.startsWith(LAUNCHER)) {
            return "neither one of the two commands nor " + LAUNCHER.strip() + ": the test cannot check it";
        }
        List<String> args = cutDown(PrintedCommands.shellWords(command.substring(LAUNCHER.length())));
        if (needsDisplay) {
            if (!GraphicsEnvironment.isHeadless()) {
                return null; // it would open a window
            }
            CliRunner r = CliRunner.run(args.toArray(String[]::new));
            return r.exitCode() == ExitCode.USAGE && r.err().contains("no display") ? null
                    : "without a display it should say so with exit 2: " + r.exitCode() + " " + r.err();
        }
        return expectOk(CliRunner.run(args.toArray(String[]::new)));
    }

    private List<String> cutDown(List<String> args) throws IOException {
        List<String> out = new ArrayList<>();
        for (int i = 0; i < args.size(); i++) {
            String a = args.get(i);
            if (OUTPUTS.contains(a) && i + 1 < args.size()) {
                out.add(a);
                out.add(dir.resolve("out-" + i + "-" + Path.of(args.get(++i)).getFileName()).toString());
            } else if (COUNTS.contains(a) && i + 1 < args.size()) {
                out.add(a);
                out.add(String.valueOf(Math.min(1, Integer.parseInt(args.get(++i)))));
            } else if (a.equals(SMOKE_FOLDER)) {
                out.add(ResultsFolders.tinyReference().toString());
            } else {
                out.add(a);
            }
        }
        if (!out.isEmpty() && out.get(0).equals("run") && !out.contains("--dry-run")) {
            out.add("--dry-run");
        }
        return out;
    }

    private static String expectOk(CliRunner r) {
        return r.exitCode() == ExitCode.OK ? null : "exit " + r.exitCode() + ": " + r.err();
    }

    /** The command lines of the README's shell blocks (fences with no language, sh or shell). */
    static List<String> commands(String markdown) {
        List<String> commands = new ArrayList<>();
        boolean shell = false;
        boolean fenced = false;
        for (String line : markdown.split("\\R")) {
            if (line.startsWith("```")) {
                String language = line.substring(3).strip();
                shell = !fenced && (language.isEmpty() || language.equals("sh") || language.equals("shell"));
                fenced = !fenced;
            } else if (fenced && shell && !line.isBlank() && !line.strip().startsWith("#")) {
                commands.add(line.strip());
            }
        }
        if (fenced) {
            fail("a fenced block of the README is not closed");
        }
        return commands;
    }
}
