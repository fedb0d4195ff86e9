package sitcov.builtin;

/** Where the autonomous car is in passing parked cars (faults/README.md, "The car under test, the traffic and the oracle"). */
public enum OvertakingStage {
    NOT_OVERTAKING,
    /** Behind a parked car, waiting for the oncoming lane to clear. */
    WAITING,
    /** Pulling out towards the start waypoint beside the first parked car. */
    START,
    /** In the other lane, passing the row of parked cars. */
    PULLED_OUT,
    /** Pulling back into its own lane. */
    FINISH;

    /** Whether the car is justified in being over the centre line. */
    public boolean isPassing() {
        return this == START || this == PULLED_OUT || this == FINISH;
    }
}
