package sitcov.experiment;

/**
 * What each later driver of a replication may spend, measured on what the first driver spent: the
 * paper's equal wall-clock time (not reproducible), or equal simulated ticks (reproducible). A
 * campaign's trials ({@code fixed-ticks}) have no first driver: each driver gets the same fixed ticks
 * and stops at its first map that finds the fault (experiments/README.md, "Campaigns: falsifying one version").
 */
public enum BudgetKind {
    WALL_CLOCK("wall-clock"),
    TICKS("ticks"),
    FIXED_TICKS("fixed-ticks");

    private final String key;

    BudgetKind(String key) {
        this.key = key;
    }

    public String key() {
        return key;
    }

    public static BudgetKind ofKey(String key) {
        for (BudgetKind b : values()) {
            if (b.key.equals(key)) {
                return b;
            }
        }
        throw new IllegalArgumentException("unknown budget '" + key + "'; use wall-clock or ticks");
    }
}
