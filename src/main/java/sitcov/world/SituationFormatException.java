package sitcov.world;

/** A situation file that cannot be read: names the file, the line and what was expected there. */
public final class SituationFormatException extends Exception {
    private static final long serialVersionUID = 1L;

    private final String source;
    private final int line;

    public SituationFormatException(String source, int line, String problem) {
        super(source + (line > 0 ? ":" + line : "") + ": " + problem, null, false, false);
        this.source = source;
        this.line = line;
    }

    /** The file (or other source) that was read. */
    public String source() {
        return source;
    }

    /** The 1-based line of the problem, or 0 when it concerns the whole file. */
    public int line() {
        return line;
    }
}
