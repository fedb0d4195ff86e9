package sitcov.experiment;

/** The test generators compared: run a candidate only if its coverage cell is empty, or run every candidate. */
public enum Method {
    COVERAGE_FILTER("coverage"),
    RANDOM("random");

    private final String key;

    Method(String key) {
        this.key = key;
    }

    /** The name in result files. */
    public String key() {
        return key;
    }
}
