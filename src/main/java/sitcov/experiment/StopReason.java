package sitcov.experiment;

/** What ended a driver's share of a replication: the budget it was given, or the safety limit on candidates. */
public enum StopReason {
    /** The first driver of a preset drew its {@code candidates}. */
    CANDIDATES("candidates"),
    /** A later driver spent the simulated ticks the first one spent. */
    TICKS("ticks"),
    /** A later driver spent the wall-clock time the first one spent. */
    WALL_CLOCK("wall-clock"),
    /** A later driver drew {@code candidate_limit} candidates before spending its budget (it ran too few maps). */
    CANDIDATE_LIMIT("candidate-limit"),
    /** A campaign's trial judged a map that falsified its target: found its fault, or violated its requirement. */
    FALSIFIED("falsified"),
    /** The driver ended its share before its budget was spent (it had nothing left to run). */
    DRIVER("driver");

    private final String key;

    StopReason(String key) {
        this.key = key;
    }

    public String key() {
        return key;
    }

    public static StopReason ofKey(String key) {
        for (StopReason r : values()) {
            if (r.key.equals(key)) {
                return r;
            }
        }
        throw new IllegalArgumentException("unknown stop reason '" + key + "'");
    }
}
