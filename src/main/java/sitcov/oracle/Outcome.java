package sitcov.oracle;

/** How a run ended. */
public enum Outcome {
    TARGET_REACHED,
    TIMEOUT,
    /** A faulty run stopped once its verdict was settled: at the end of the tick of its first accident the fault-free run lacks. */
    STOPPED_AT_VERDICT,
    /** The controller gave no command within its per-tick timeout. */
    CONTROLLER_TIMEOUT,
    /** The controller exited, or wrote garbage or a malformed command. */
    CONTROLLER_ERROR
}
