package sitcov.oracle;

/**
 * The near-miss measures {@link NearMisses} keeps for a run: each the least value it reached, and
 * the tick it first did. Near misses are reported beside accidents and never counted as failures.
 */
public enum NearMiss {
    /** Signed gap (m) from the car's footprint to any active moving vehicle's: negative while they overlap. */
    MOVING_GAP,
    /** Signed gap (m) from the car's footprint to any parked car's. */
    PARKED_GAP,
    /** Signed distance (m) from the footprint to the road's edge: negative while part of it is off the road. */
    ROAD_EDGE,
    /** Signed distance (m) from the footprint to the centre line, outside excused passes: negative while over it. */
    CENTRE_LINE,
    /** Time to collision with a moving vehicle (ticks), both keeping their velocities; infinite when never closing. */
    TIME_TO_COLLISION,
    /** Post-encroachment time (ticks) at a T-junction's square between the car and a moving vehicle. */
    POST_ENCROACHMENT;

    /** The name of its least value's column in runs.csv. */
    public String column() {
        return "near_" + name().toLowerCase(java.util.Locale.ROOT);
    }
}
