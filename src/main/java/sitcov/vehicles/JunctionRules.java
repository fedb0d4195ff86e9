package sitcov.vehicles;

/**
 * Distances every car keeps at junctions, the car under test's builtin controller and the moving
 * cars alike: where a car waits, where its crossing ends, and when a crossing has gone wrong.
 */
public final class JunctionRules {
    /** A crossing ends at its exit waypoint, this far beyond the square along the exit lane. */
    public static final double EXIT_BEYOND_SQUARE = 1.5;
    /** A crossing that has taken the car this far from the junction's centre has gone wrong: give it up. */
    public static final double STRAYED = 12;
    /**
     * Where every car waits short of a junction's square it may not enter yet: back far enough
     * that a car turning through the square, whose corners swing wide, passes clear of it.
     */
    public static final double WAIT_SHORT_OF_SQUARE = 2.5;

    private JunctionRules() {
    }
}
