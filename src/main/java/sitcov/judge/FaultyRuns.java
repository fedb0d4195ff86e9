package sitcov.judge;

/**
 * How long an experiment runs each faulty run (preset key {@code faulty_runs}). Both give the same
 * verdicts: a faulty run's verdict is settled at its first accident the fault-free run lacks (it
 * is then FOUND under the differential oracle and under the paper's notion), and nothing later
 * can change it. What differs is what the run costs and what its row counts after that moment.
 */
public enum FaultyRuns {
    /** Stop at the end of the tick the verdict is settled; runs.csv says STOPPED_AT_VERDICT and the ticks run. */
    UNTIL_VERDICT("until-verdict"),
    /** Drive on to the Target or the timeout, as the paper did: every accident of the run is counted. */
    TO_END("to-end");

    private final String key;

    FaultyRuns(String key) {
        this.key = key;
    }

    public String key() {
        return key;
    }

    public static FaultyRuns ofKey(String key) {
        for (FaultyRuns f : values()) {
            if (f.key.equals(key)) {
                return f;
            }
        }
        throw new IllegalArgumentException("unknown faulty_runs '" + key + "'; use until-verdict or to-end");
    }
}
