package sitcov.stats;

import java.util.Locale;

/**
 * Conventional magnitude of an effect size, as reports name it (see {@link VarghaDelaney#magnitude});
 * {@code UNDEFINED} where there was nothing to compare (an empty sample).
 */
public enum EffectSize {
    NEGLIGIBLE, SMALL, MEDIUM, LARGE, UNDEFINED;

    /** The lower-case name for tables and prose: "negligible", "small", "medium", "large", "undefined". */
    public String label() {
        return name().toLowerCase(Locale.ROOT);
    }
}
