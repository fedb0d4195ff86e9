package sitcov.cli;

import java.io.PrintStream;
import java.util.List;

/** A command that is part of sitcov's design but not built yet; it says so instead of pretending. */
record PlannedCommand(String name, String synopsis, String summary) implements Command {
    @Override
    public int run(List<String> args, PrintStream out, PrintStream err) {
        err.println("sitcov: '" + name + "' is not available yet in sitcov " + Version.current()
                + " (planned: " + summary + ").");
        return ExitCode.FAILURE;
    }
}
