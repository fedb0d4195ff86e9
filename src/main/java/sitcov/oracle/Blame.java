package sitcov.oracle;

/**
 * The named rules that decide whether a contact with a moving car is the autonomous car's fault.
 * The first that applies wins, in this order.
 */
public enum Blame {
    /** Standing still, the car cannot be at fault. */
    EXCUSED_STANDING_STILL,
    /** Hit from behind by a faster car going the same way. */
    EXCUSED_HIT_FROM_BEHIND,
    /** The other car was over the centre line. */
    EXCUSED_OTHER_ON_CENTRE_LINE,
    /** The other car came the other way in the car's own lane while the car kept to it. */
    EXCUSED_OTHER_IN_WRONG_LANE,
    /** None of the excuses applies: an accident. */
    AT_FAULT;

    public boolean isAccident() {
        return this == AT_FAULT;
    }
}
