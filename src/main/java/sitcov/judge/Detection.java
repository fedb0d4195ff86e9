package sitcov.judge;

/** What one seeded fault did on one map and internal seed, judged by the differential oracle. */
public enum Detection {
    /** The faulty code path never ran. */
    NOT_REACHED,
    /** The faulty code path ran but never changed a value the car used. */
    REACHED_NO_EFFECT,
    /** The fault changed what the car did, but caused no accident the fault-free run lacks. */
    EFFECT_NO_FAILURE,
    /** The faulty run has an accident event the fault-free run of the same seeds does not have. */
    FOUND;

    public boolean found() {
        return this == FOUND;
    }
}
