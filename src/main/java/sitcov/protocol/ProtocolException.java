package sitcov.protocol;

/** A message that breaks the protocol: not JSON, the wrong type, a missing or malformed member. */
public final class ProtocolException extends Exception {
    private static final long serialVersionUID = 1L;

    public ProtocolException(String message) {
        super(message, null, false, false);
    }
}
