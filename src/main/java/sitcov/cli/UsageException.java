package sitcov.cli;

/** A user mistake on the command line or in an input file: reported in one line, exit code 2. */
public final class UsageException extends Exception {
    private static final long serialVersionUID = 1L;

    public UsageException(String message) {
        super(message, null, false, false);
    }
}
