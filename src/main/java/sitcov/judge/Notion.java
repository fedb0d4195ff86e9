package sitcov.judge;

/**
 * When a seeded fault counts as found on a map (faults/README.md, "The car under test, the traffic and the oracle"):
 * by the differential oracle (the faulty run has an accident the fault-free run of the same
 * seeds lacks) or by the paper's weaker notion (the fault was triggered and the faulty run had any
 * accident). Each carries its name in the tables ({@link #key()}) and in the figures ({@link #label()}).
 */
public enum Notion {
    DIFFERENTIAL("differential", "differential oracle (new accident)"),
    PAPER("paper", "paper's notion (any accident)");

    private final String key;
    private final String label;

    Notion(String key, String label) {
        this.key = key;
        this.label = label;
    }

    /** The short name, as in the {@code notion} column of summary.csv and table2.csv. */
    public String key() {
        return key;
    }

    /** The long name, as in the figures' panel titles. */
    public String label() {
        return label;
    }
}
