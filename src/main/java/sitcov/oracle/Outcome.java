package sitcov.oracle;

/** How a run ended. */
public enum Outcome {
    TARGET_REACHED,
    TIMEOUT
}
