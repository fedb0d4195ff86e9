package sitcov.control;

/**
 * A controller that could not give this tick's command: it gave no answer in time, or it exited,
 * wrote garbage or a malformed command. The run ends with the matching outcome; the experiment goes
 * on (experiments/controllers/README.md, "Testing your own controller").
 */
public final class ControllerFailure extends RuntimeException {
    /** What went wrong, as the run's outcome names it. */
    public enum Kind {
        /** No answer within the per-tick timeout. */
        TIMEOUT,
        /** An exit, garbage, or a malformed command. */
        ERROR
    }

    private final Kind kind;

    public ControllerFailure(Kind kind, String message) {
        super(message, null, false, false);
        this.kind = kind;
    }

    public Kind kind() {
        return kind;
    }
}
