package sitcov.control;

/**
 * Controllers of several runs stepped together (batched lockstep, README "The protocol"): slot s
 * holds one run at a time; its controllers are {@link DeferredController}s, which take the tick's
 * observation and wait; one {@link #exchange} answers every waiting observation at once.
 */
public interface ControllerBatch {
    /** How many runs are stepped together: the number of slots. */
    int size();

    /** Makes the controller of each run slot {@code slot} holds, one run after another. */
    ControllerFactory slot(int slot);

    /**
     * Answers every observation taken since the last exchange; each run then reads its command at
     * its step. A controller that fails fails every waiting run, with its reason.
     */
    void exchange();
}
