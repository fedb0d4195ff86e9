package sitcov.stats;

import java.util.Locale;

/** Conventional magnitude of an effect size, as reports name it (see {@link VarghaDelaney#magnitude}). */
public enum EffectSize {
    NEGLIGIBLE, SMALL, MEDIUM, LARGE;

    /** The lower-case name for tables and prose: "negligible", "small", "medium", "large". */
    public String label() {
        return name().toLowerCase(Locale.ROOT);
    }
}
