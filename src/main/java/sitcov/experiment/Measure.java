package sitcov.experiment;

/**
 * The measures two drivers are compared on, each a value per driver and replication, with the
 * margin within which two drivers count as equivalent unless a preset declares its own
 * ({@code margin_KEY=}): a difference smaller than the margin is too small to matter. Named here,
 * where a preset's {@link AnalysisPlan} picks them; computed in {@code sitcov.analysis.Metrics}.
 */
public enum Measure {
    CELLS_COVERED("cells_covered", "cells covered", "cells covered", "cells", 5),
    MAPS_RUN("maps_run", "maps run", "maps run", "maps", 5),
    FAULTS_FOUND("faults_found", "distinct faults found", "distinct faults found", "faults", 1),
    AVG_MAP_FAULT("avg_map_fault", "faults found per map (avg-map-fault)", "faults found per map", "faults a map", 0.1),
    PROP_MAP_ALL_FAULT("prop_map_all_fault", "share of maps finding every fault (prop-map-all-fault)",
            "share of maps finding every fault", "", 0.01),
    DISCOVERY_AREA("discovery_area", "area under faults found against ticks", "area under faults-vs-ticks", "", 0.02),
    /** Maps whose reference run failed (an accident or the controller's failure): the reference's own failures. */
    OWN_FAILURES("own_failures", "own failures of the reference (maps)", "own failures", "maps", 1),
    /** The reference's own failures counted once per cell × failure type. */
    DISTINCT_OWN_FAILURES("distinct_own_failures", "distinct own failures of the reference (cell × failure type)",
            "distinct own failures", "failures", 1);

    /** The paper's measures, compared in every experiment; the own-failure ones join them when a preset asks. */
    public static final java.util.List<Measure> PAPER = java.util.List.of(CELLS_COVERED, MAPS_RUN, FAULTS_FOUND,
            AVG_MAP_FAULT, PROP_MAP_ALL_FAULT, DISCOVERY_AREA);

    /** Whether the measure counts the reference's own failures rather than its variants'. */
    public boolean ofOwnFailures() {
        return this == OWN_FAILURES || this == DISTINCT_OWN_FAILURES;
    }

    private final String key;
    private final String words;
    private final String label;
    private final String unit;
    private final double defaultMargin;

    Measure(String key, String words, String label, String unit, double defaultMargin) {
        this.key = key;
        this.words = words;
        this.label = label;
        this.unit = unit;
        this.defaultMargin = defaultMargin;
    }

    /** The measure's name in presets, manifests and stats.csv. */
    public String key() {
        return key;
    }

    public String words() {
        return words;
    }

    /** The measure's short name, for a figure's axis or a table's column head. */
    public String label() {
        return label;
    }

    /** What one unit of the measure counts ("faults"), or empty for a share. */
    public String unit() {
        return unit;
    }

    public double defaultMargin() {
        return defaultMargin;
    }

    public static Measure ofKey(String key) {
        for (Measure m : values()) {
            if (m.key.equals(key)) {
                return m;
            }
        }
        throw new IllegalArgumentException("unknown measure '" + key + "'; the measures are "
                + java.util.Arrays.stream(values()).map(Measure::key).toList());
    }
}
