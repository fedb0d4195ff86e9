package sitcov.oracle;

/**
 * One accident event: the tick the car entered the state, where its front centre was, and the
 * other party (a parked car's or moving car's id; -1 when there is none).
 */
public record Accident(long tick, AccidentType type, double x, double y, int otherParty) {
    /** The same accident, ignoring when and where: what the differential oracle compares. */
    public String signature() {
        return type + (otherParty >= 0 ? "#" + otherParty : "");
    }
}
