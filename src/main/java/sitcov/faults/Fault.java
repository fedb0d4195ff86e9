package sitcov.faults;

import java.util.Optional;

/**
 * The twenty seeded faults of the autonomous car, by id. Each can be switched on for a run; the
 * paper's Table 1 used the seven marked with a paper id.
 */
public enum Fault {
    STALE_WAYPOINT_IDENTITY(0, "stale-waypoint-identity",
            "a new waypoint is registered under the previous waypoint's identity, so the car may keep steering at a stale one"),
    WAYPOINTS_NORTH_WEST(1, "waypoints-north-west", "waypoints are placed 1 m west and 1 m north of where they belong"),
    WAYPOINTS_NORTH_EAST(2, "waypoints-north-east", "waypoints are placed 1 m east and 1 m north of where they belong"),
    WAYPOINTS_SOUTH_WEST(3, "waypoints-south-west", "waypoints are placed 1 m west and 1 m south of where they belong"),
    WAYPOINTS_SOUTH_EAST(4, "waypoints-south-east", "waypoints are placed 1 m east and 1 m south of where they belong"),
    CRAWL_DOUBLE_ACCELERATION(5, "crawl-double-acceleration", "when crawling, the car accelerates twice per tick"),
    CRAWL_DOUBLE_BRAKING(6, "crawl-double-braking", "when crawling, the car brakes twice per tick"),
    HALF_THE_JUNCTIONS(7, "half-the-junctions",
            "only the first half of the junctions is recognised: no slowing, no waiting, no exit choice at the rest"),
    MARKING_ARC_FIRST_HALF_REMOVED(8, "marking-arc-first-half-removed",
            "the first (left, kerb-side) half of the road-marking scan arc is removed"),
    MARKING_ARC_SECOND_HALF_REMOVED(9, "marking-arc-second-half-removed",
            "the second (right, centre-side) half of the road-marking scan arc is removed"),
    MARKING_HALF_ANGULAR_RESOLUTION(10, "marking-half-angular-resolution",
            "the road-marking search runs at half its angular resolution (1 degree instead of 0.5)"),
    MARKING_SCAN_STARTS_HALF_WAY(11, "marking-scan-starts-half-way",
            "the road-marking scan starts half-way along its range, so it misses near markings"),
    MARKING_HALF_RANGE(12, "marking-half-range", "the road-marking scan reaches only half its range"),
    MARKING_HALF_RANGE_RESOLUTION(13, "marking-half-range-resolution",
            "the road-marking scan samples at half its range resolution (1 m instead of 0.5 m)"),
    TARGET_LANE_CHECK_SKIPPED(14, "target-lane-check-skipped",
            "near the Target, the car skips the check that the Target is in its own lane"),
    CREEPS_WHILE_WAITING(15, "creeps-while-waiting", "the car creeps forward while waiting at an occupied junction"),
    SECOND_PULL_OUT(16, "second-pull-out",
            "while overtaking, the car issues a second pull-out waypoint instead of passing the row of parked cars"),
    STOPS_TURNING_WHILE_OVERTAKING(17, "stops-turning-while-overtaking",
            "while overtaking, the car stops turning towards its current waypoint"),
    OBSTACLE_SEARCH_ALONG_HEADING(18, "obstacle-search-along-heading",
            "while overtaking, the car looks for obstacles only along its current heading, not its intended direction of travel"),
    ONCOMING_AT_HALF_SPEED(19, "oncoming-at-half-speed",
            "judging whether it is safe to overtake, the car assumes oncoming cars move at half their speed");

    private final int id;
    private final String label;
    private final String description;

    Fault(int id, String label, String description) {
        this.id = id;
        this.label = label;
        this.description = description;
    }

    public int id() {
        return id;
    }

    /** A short kebab-case name, as used in the catalogue and in result files. */
    public String label() {
        return label;
    }

    public String description() {
        return description;
    }

    /** The id the paper's Table 1 gives this fault, if it was one of the paper's seven. */
    public Optional<Integer> paperId() {
        return switch (this) {
            case WAYPOINTS_NORTH_EAST, WAYPOINTS_SOUTH_EAST, MARKING_ARC_FIRST_HALF_REMOVED,
                    MARKING_HALF_ANGULAR_RESOLUTION, MARKING_HALF_RANGE, STOPS_TURNING_WHILE_OVERTAKING,
                    OBSTACLE_SEARCH_ALONG_HEADING -> Optional.of(id);
            default -> Optional.empty();
        };
    }

    public static Fault ofId(int id) {
        for (Fault f : values()) {
            if (f.id == id) {
                return f;
            }
        }
        throw new IllegalArgumentException("no fault has id " + id + "; the ids are 0 to " + (values().length - 1));
    }
}
