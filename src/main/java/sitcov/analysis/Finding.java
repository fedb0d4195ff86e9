package sitcov.analysis;

/** What a comparison of two drivers on one measure or fault shows, in the words a verdict uses. */
public enum Finding {
    /** The earlier driver is higher: a difference shown. */
    HIGHER_A("higher-a"),
    /** The later driver is higher. */
    HIGHER_B("higher-b"),
    /** The difference is shown to lie within the measure's margin. */
    EQUIVALENT("equivalent"),
    /** Neither a difference nor equivalence shown: the CI says what remains possible. */
    INCONCLUSIVE("inconclusive"),
    /** So few replications differ that no signed-rank test could reach the level: described, not tested. */
    TOO_FEW("too-few-replications"),
    /** Nothing to test: constant, a duplicate of another measure, or a fault found by neither driver or on every map by both. */
    NOT_TESTABLE("not-testable");

    private final String key;

    Finding(String key) {
        this.key = key;
    }

    public String key() {
        return key;
    }

    /** Whether a test of this finding was counted in the family (or was the primary test). */
    public boolean tested() {
        return this != TOO_FEW && this != NOT_TESTABLE;
    }
}
