package sitcov.cli;

/** The exit codes of the sitcov command line. */
public final class ExitCode {
    /** The command did what was asked. */
    public static final int OK = 0;
    /** The command ran but could not finish what was asked. */
    public static final int FAILURE = 1;
    /** A user mistake: unknown command or option, bad value, unreadable input. */
    public static final int USAGE = 2;

    private ExitCode() {
    }
}
