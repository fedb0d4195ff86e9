package sitcov.world;

/**
 * The generator's key random choices, the ones a proposal may re-weight to estimate a failure rate
 * by importance sampling. Each is one uniform number u in [0, 1) split into equal bins: a count
 * takes bin b as its value's offset ({@code (int) (u * bins)}, as the generator always drew it),
 * a coordinate keeps u itself, so a proposal over its bins is a piecewise-constant density.
 */
public enum DrawSite {
    /** How many T-junctions the road tree tries to add: 5 + bin. */
    JUNCTION_ATTEMPTS("junctions", 20, true),
    /** How many parked cars are placed: 5 + bin. */
    PARKED_CARS("parked", 5, true),
    /** How many moving cars are placed: 5 + bin. */
    MOVING_CARS("moving", 15, true),
    /** Each try at the Target's x, across the world's width. */
    TARGET_X("target-x", 5, false),
    /** Each try at the Target's y, across the world's height. */
    TARGET_Y("target-y", 4, false),
    /** Each try at the car's start, x. */
    START_X("start-x", 5, false),
    /** Each try at the car's start, y. */
    START_Y("start-y", 4, false);

    private final String key;
    private final int bins;
    private final boolean count;

    DrawSite(String key, int bins, boolean count) {
        this.key = key;
        this.bins = bins;
        this.count = count;
    }

    /** Its name in presets and results files. */
    public String key() {
        return key;
    }

    public int bins() {
        return bins;
    }

    /** Whether the draw is a count (its bin is the value) rather than a coordinate. */
    public boolean isCount() {
        return count;
    }

    /** The site named {@code key}, or null. */
    public static DrawSite byKey(String key) {
        for (DrawSite s : values()) {
            if (s.key.equals(key)) {
                return s;
            }
        }
        return null;
    }
}
