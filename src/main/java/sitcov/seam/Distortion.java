package sitcov.seam;

import sitcov.control.Observation;

/**
 * What one seam fault does in one run, and the state it keeps doing it (its random stream, frames it
 * remembers, commands it holds back). The state moves on the same way whether the fault acts or is
 * only watched from the shadows, so a run forked where the fault departs goes on as a whole faulty run.
 */
sealed interface Distortion permits ObservationView, CommandDistortion {
    /** Before the controller steps in tick {@code tick}: draws from its stream, starts or ends an episode. */
    void startTick(Observation real, long tick);

    /** Whether its condition holds this tick (a dropped radar frame, a frozen episode): where it is reached. */
    boolean acting();
}
