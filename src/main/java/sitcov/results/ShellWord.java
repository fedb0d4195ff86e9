package sitcov.results;

import java.util.regex.Pattern;

/** Text as one word of a POSIX shell, for the commands sitcov prints to be typed as printed. */
public final class ShellWord {
    /** What a shell neither splits nor expands. */
    private static final Pattern PLAIN = Pattern.compile("[A-Za-z0-9_./:,=@%+-]+");

    private ShellWord() {
    }

    /** {@code text} in single quotes, each of its own written '\''. */
    public static String quoted(String text) {
        return "'" + text.replace("'", "'\\''") + "'";
    }

    /** {@code text} as it is where the shell would read it as one word, else {@link #quoted}. */
    public static String of(String text) {
        return PLAIN.matcher(text).matches() ? text : quoted(text);
    }
}
