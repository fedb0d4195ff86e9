package sitcov.cli;

import java.io.PrintStream;
import java.util.List;

/** One sitcov command, such as {@code map} or {@code simulate}. */
public interface Command {
    /** The word that selects the command. */
    String name();

    /** The arguments the command takes, as shown in help, e.g. {@code --seed S [--png FILE]}. */
    String synopsis();

    /** One line on what the command does. */
    String summary();

    /**
     * Runs the command with the arguments that follow its name.
     *
     * @return an {@link ExitCode}
     * @throws UsageException for a user mistake; the caller prints it and exits with 2
     */
    int run(List<String> args, PrintStream out, PrintStream err) throws UsageException;
}
