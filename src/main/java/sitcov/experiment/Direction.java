package sitcov.experiment;

import sitcov.stats.WilcoxonSignedRank.Alternative;

/** Which way a primary question looks: at a difference either way, or at the first named driver being higher or lower. */
public enum Direction {
    TWO_SIDED("two-sided"),
    HIGHER("higher"),
    LOWER("lower");

    private final String key;

    Direction(String key) {
        this.key = key;
    }

    public String key() {
        return key;
    }

    /** The signed-rank test's alternative for differences taken as the first named driver minus the second ({@code asNamed}) or the reverse. */
    public Alternative alternative(boolean asNamed) {
        return switch (this) {
            case TWO_SIDED -> Alternative.TWO_SIDED;
            case HIGHER -> asNamed ? Alternative.GREATER : Alternative.LESS;
            case LOWER -> asNamed ? Alternative.LESS : Alternative.GREATER;
        };
    }

    public static Direction ofKey(String key) {
        for (Direction d : values()) {
            if (d.key.equals(key)) {
                return d;
            }
        }
        throw new IllegalArgumentException("unknown primary_direction '" + key + "'; use two-sided, higher or lower"
                + " (higher: the first of primary_drivers is higher)");
    }
}
