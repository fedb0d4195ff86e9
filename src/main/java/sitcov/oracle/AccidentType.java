package sitcov.oracle;

/** The kinds of accident the oracle detects (README, "The car under test, the traffic and the oracle"). */
public enum AccidentType {
    /** The car's footprint overlaps a parked car. */
    CLASHWITHOBSTACLE,
    /** The car's footprint overlaps a moving car, and the blame rules put it at fault. */
    CLASHWITHOTHERCAR,
    /** Some part of the car's footprint is off the road surface. */
    LEAVEROAD,
    /** The car is over the centre line without overtaking or turning through a junction. */
    CROSSCENTRELINE,
    /** The Target was not reached in 5000 ticks. */
    TIMEOUT
}
