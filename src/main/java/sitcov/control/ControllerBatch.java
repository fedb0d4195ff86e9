package sitcov.control;

/**
 * Controllers of several runs stepped together (experiments/controllers/README.md, "Batches"):
 * slot s holds one run at a time; its controllers are {@link DeferredController}s, which take the
 * tick's observation and wait. {@link #send} sends every observation taken since the last send in one
 * message; {@link #receive} reads the answer to the oldest message not yet answered and hands each
 * run its command. Up to two messages may wait for their answers, so that the runs of one are
 * stepped while the controller works on the other.
 */
public interface ControllerBatch {
    /** How many runs are stepped together: the number of slots. */
    int size();

    /** Makes the controller of each run slot {@code slot} holds, one run after another. */
    ControllerFactory slot(int slot);

    /** Sends the observations taken since the last send, if any, as one message. */
    void send();

    /**
     * Reads the answer to the oldest message sent and not yet answered; each of its runs then reads
     * its command at its step. A controller that fails fails every waiting run, with its reason.
     */
    void receive();

    /** Sends the observations taken since the last send and reads their answer. */
    default void exchange() {
        send();
        receive();
    }
}
