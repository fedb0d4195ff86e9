package sitcov.oracle;

import java.util.Optional;

/**
 * What counts as a failure of the controller under test: an accident of each type, and the
 * controller's own failure to give a command (no answer in time, an exit, garbage). The
 * differential oracle judges both alike: a version fails where the reference did not.
 */
public enum Failure {
    CLASHWITHOBSTACLE,
    CLASHWITHOTHERCAR,
    LEAVEROAD,
    CROSSCENTRELINE,
    TIMEOUT,
    /** The controller gave no command within its per-tick timeout. */
    CONTROLLER_TIMEOUT,
    /** The controller exited, or wrote garbage or a malformed command. */
    CONTROLLER_ERROR;

    public static Failure of(AccidentType type) {
        return values()[type.ordinal()];
    }

    /** The controller's failure a run ended in, if it did. */
    public static Optional<Failure> of(Outcome outcome) {
        return switch (outcome) {
            case CONTROLLER_TIMEOUT -> Optional.of(CONTROLLER_TIMEOUT);
            case CONTROLLER_ERROR -> Optional.of(CONTROLLER_ERROR);
            default -> Optional.empty();
        };
    }

    /** Its name in a file's column or cell: an accident type's as its runs.csv column names it. */
    public String column() {
        return name().toLowerCase(java.util.Locale.ROOT);
    }

    /** Whether the controller itself failed, rather than the car having an accident. */
    public boolean ofController() {
        return this == CONTROLLER_TIMEOUT || this == CONTROLLER_ERROR;
    }
}
