package sitcov.protocol;

/** A controller that could not be started or failed the handshake; the message names its command. */
public final class ControllerStartException extends Exception {
    private static final long serialVersionUID = 1L;

    public ControllerStartException(String message) {
        super(message, null, false, false);
    }
}
