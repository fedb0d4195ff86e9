package sitcov.control;

import java.util.Arrays;
import java.util.Optional;

/**
 * Ground truth a controller may ask for by name. Not a sensor: the world's exact values, for
 * controllers that test one part (say, planning) without the perception before it. The lane is the
 * one the car's front centre is in, taken to run along the compass direction nearest its heading.
 */
public enum Channel {
    /** Metres from the lane's centre line to the car's front centre, positive to the right. */
    LANE_OFFSET("lane_offset"),
    /** Degrees from the lane's direction to the car's heading, in (−180, 180], positive towards larger bearings (a turn to the left, as steering). */
    HEADING_ERROR("heading_error"),
    /** Metres along the lane from the car's front to the next junction's square ahead; NaN when none. */
    DISTANCE_TO_JUNCTION("distance_to_junction"),
    /** Metres from the car's front centre to the Target. */
    TARGET_DISTANCE("target_distance");

    private final String wireName;

    Channel(String wireName) {
        this.wireName = wireName;
    }

    /** Its name in presets and the protocol. */
    public String wireName() {
        return wireName;
    }

    public static Optional<Channel> ofWireName(String name) {
        return Arrays.stream(values()).filter(c -> c.wireName.equals(name)).findFirst();
    }
}
