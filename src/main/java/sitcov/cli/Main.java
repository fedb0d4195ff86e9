package sitcov.cli;

import java.io.PrintStream;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.stream.Collectors;
import sitcov.drivers.Drivers;

/**
 * The sitcov command line. {@link #main} is a thin shell over {@link #run}, which tests call
 * directly with their own streams and read the exit code from.
 */
public final class Main {
    /** The program's name, before its messages. */
    static final String PROGRAM = "sitcov";
    /**
     * How a user starts sitcov from the repository's root: the launcher script, which builds the jar when it is
     * missing or stale and runs it. Every usage line and every command sitcov prints for a user names it.
     */
    static final String LAUNCHER = "experiments/sitcov";
    private static final String HELP_HINT = "Run '" + LAUNCHER + " --help' for usage.";

    private final Map<String, Command> commands = new LinkedHashMap<>();

    Main(List<Command> commands) {
        for (Command command : commands) {
            this.commands.put(command.name(), command);
        }
    }

    /** The commands of this version of sitcov, in the order help lists them. */
    static Main standard() {
        return new Main(List.of(
                new RunCommand(Drivers.standard()),
                new MergeCommand(),
                new ReportCommand(),
                new ReplayCommand(),
                new ExportCommand(),
                new ViewCommand(),
                new SimulateCommand(),
                new EstimateCommand(),
                new MapCommand(),
                new CoverageCommand(),
                new FaultsCommand(),
                new VersionsCommand(),
                new BenchCommand(),
                new ControllerCommand()));
    }

    public static void main(String[] args) {
        int code = run(args, System.out, System.err);
        System.out.flush();
        System.err.flush();
        if (code != ExitCode.OK) {
            System.exit(code);
        }
    }

    /** Runs sitcov with {@code args}; returns the exit code instead of exiting. */
    public static int run(String[] args, PrintStream out, PrintStream err) {
        return standard().execute(args, out, err);
    }

    int execute(String[] args, PrintStream out, PrintStream err) {
        try {
            return dispatch(Arrays.asList(args), out, err);
        } catch (UsageException e) {
            err.println(PROGRAM + ": " + e.getMessage());
            err.println(HELP_HINT);
            return ExitCode.USAGE;
        }
    }

    private int dispatch(List<String> args, PrintStream out, PrintStream err) throws UsageException {
        if (args.isEmpty()) {
            return defaultExperiment(out, err);
        }
        String first = args.get(0);
        switch (first) {
            case "--help", "-h", "help" -> {
                printHelp(out);
                return ExitCode.OK;
            }
            case "--version", "-V" -> {
                out.println(PROGRAM + " " + Version.current());
                return ExitCode.OK;
            }
            default -> {
                // fall through to command lookup below
            }
        }
        if (first.startsWith("-")) {
            throw new UsageException("unknown option '" + first + "'; options go after a command, "
                    + "and the only options on their own are --help and --version.");
        }
        Command command = commands.get(first);
        if (command == null) {
            throw new UsageException("unknown command '" + first + "'; the commands are "
                    + String.join(", ", commands.keySet()) + ".");
        }
        List<String> rest = args.subList(1, args.size());
        if (rest.contains("--help") || rest.contains("-h")) {
            printCommandHelp(command, out);
            return ExitCode.OK;
        }
        return command.run(rest, out, err);
    }

    private int defaultExperiment(PrintStream out, PrintStream err) throws UsageException {
        Command run = commands.get("run");
        return run.run(List.of("paper-rq1"), out, err);
    }

    private void printHelp(PrintStream out) {
        int width = commands.keySet().stream().mapToInt(String::length).max().orElse(0);
        out.println(PROGRAM + " " + Version.current()
                + " - situation-coverage testing of a simulated autonomous car");
        out.println();
        out.println("Usage: " + LAUNCHER + " [COMMAND [OPTIONS]]");
        out.println("       " + LAUNCHER + " --help | --version");
        out.println();
        out.println("With no command, runs the paper's comparison (run paper-rq1), as mvn -q compile exec:java does.");
        out.println();
        out.println("Commands:");
        out.print(commands.values().stream()
                .map(c -> String.format("  %-" + width + "s  %s%n", c.name(), c.summary()))
                .collect(Collectors.joining()));
        out.println();
        out.println("Run '" + LAUNCHER + " COMMAND --help' for a command's options.");
        out.println("Exit codes: 0 done, 1 failed, 2 bad input.");
    }

    private static void printCommandHelp(Command command, PrintStream out) {
        out.println("Usage: " + LAUNCHER + " " + command.name()
                + (command.synopsis().isEmpty() ? "" : " " + command.synopsis()));
        out.println();
        out.println(command.summary());
    }
}
