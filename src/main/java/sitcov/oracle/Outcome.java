package sitcov.oracle;

/** How a run ended. */
public enum Outcome {
    TARGET_REACHED,
    TIMEOUT,
    /** A faulty run stopped once its verdict was settled: at the end of the tick of its first accident the fault-free run lacks. */
    STOPPED_AT_VERDICT
}
