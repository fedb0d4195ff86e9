package sitcov.analysis;

import sitcov.experiment.AnalysisPlan;

/**
 * The exploratory tests of a comparison, in their two families. Measures: {@code places} measures of
 * pairs, holding {@code differences} difference and {@code equivalences} equivalence tests, closed
 * testing keeping the family-wise error at 5 %. Faults: {@code faults} per-fault tests screened by
 * Benjamini–Hochberg at a 5 % false-discovery rate, {@code discoveries} of them flagged.
 */
public record Families(int places, int differences, int equivalences, int faults, int discoveries) {
    /**
     * The level a measure's test is held to at most, Holm's first step over the places: what "could
     * have detected" is computed at (the closed procedure's later steps only loosen it).
     */
    public double measureLevel() {
        return AnalysisPlan.ALPHA / Math.max(1, places);
    }

    /**
     * The level a fault's test needed to be flagged: for a flagged one, Benjamini–Hochberg's bound at the
     * number flagged (R·5 %/m); for another, the bound at which it would have joined them ((R + 1)·5 %/m).
     */
    public double faultLevel(boolean flagged) {
        return Math.min(AnalysisPlan.ALPHA, AnalysisPlan.ALPHA * (flagged ? discoveries : discoveries + 1)
                / Math.max(1, faults));
    }

    public int tests() {
        return differences + equivalences + faults;
    }
}
