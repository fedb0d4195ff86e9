package sitcov.builtin;

/** A point the autonomous car steers at, under an identity it looks it up by. */
public record Waypoint(int id, double x, double y, Kind kind) {
    /** What a waypoint is for. */
    public enum Kind {
        JUNCTION_EXIT,
        OVERTAKE_START,
        OVERTAKE_PULLED_OUT,
        OVERTAKE_FINISH
    }
}
