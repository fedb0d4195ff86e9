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
    /**
     * The car under test may claim a junction only while its front centre is this near the
     * junction's square (0 inside it): more than the 23.75 m a car needs to stop from full speed, so
     * a car that slows for a junction can always have asked in time (experiments/controllers/README.md, "How the car
     * moves").
     */
    public static final double CLAIM_WITHIN = 30;
    /**
     * The car under test may hold, and ask for, at most this many junctions at once (after the
     * command's releases): the one it crosses, the next, and the one after, for squares can be as
     * little as 2 m apart (experiments/controllers/route_driver.py holds three on such maps).
     */
    public static final int MAX_HELD = 3;

    private JunctionRules() {
    }
}
