package sitcov.export;

import java.util.ArrayDeque;
import java.util.Deque;
import java.util.Locale;

/**
 * A small XML writer: elements with attributes given as name–value pairs, indented two spaces,
 * text escaped. Numbers are written with a fixed number of decimals in the root locale, so a
 * document is the same bytes on every machine.
 */
final class Xml {
    private final StringBuilder text = new StringBuilder(4096);
    private final Deque<String> open = new ArrayDeque<>();
    /** Inside a one-line block: no line breaks, no indentation. */
    private boolean oneLine;

    Xml() {
        text.append("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    }

    Xml open(String name, String... attributes) {
        start(name, attributes);
        text.append('>');
        newline();
        open.push(name);
        return this;
    }

    Xml empty(String name, String... attributes) {
        start(name, attributes);
        text.append("/>");
        newline();
        return this;
    }

    Xml close() {
        String name = open.pop();
        indent();
        text.append("</").append(name).append('>');
        newline();
        return this;
    }

    /**
     * Writes what follows on one line at the margin, until {@link #endLine()}: a trajectory's many
     * small vertices read better, and take a third of the bytes, one to a line, and its indentation
     * would be a fifth of a vertex's bytes.
     */
    Xml startLine() {
        oneLine = true;
        return this;
    }

    Xml endLine() {
        oneLine = false;
        text.append('\n');
        return this;
    }

    Xml comment(String words) {
        indent();
        text.append("<!-- ").append(escape(words.replace("--", "- -"))).append(" -->\n");
        return this;
    }

    String document() {
        if (!open.isEmpty()) {
            throw new IllegalStateException("elements left open: " + open);
        }
        return text.toString();
    }

    private void start(String name, String[] attributes) {
        if (attributes.length % 2 != 0) {
            throw new IllegalArgumentException("attributes of " + name + " come in name-value pairs");
        }
        indent();
        text.append('<').append(name);
        for (int i = 0; i < attributes.length; i += 2) {
            text.append(' ').append(attributes[i]).append("=\"").append(escape(attributes[i + 1])).append('"');
        }
    }

    private void indent() {
        if (!oneLine) {
            text.append("  ".repeat(open.size()));
        }
    }

    private void newline() {
        if (!oneLine) {
            text.append('\n');
        }
    }

    static String escape(String s) {
        StringBuilder out = new StringBuilder(s.length());
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            switch (c) {
                case '&' -> out.append("&amp;");
                case '<' -> out.append("&lt;");
                case '>' -> out.append("&gt;");
                case '"' -> out.append("&quot;");
                case '\n' -> out.append("&#10;");
                default -> out.append(c);
            }
        }
        return out.toString();
    }

    /** The decimals a length or coordinate in metres is written with: to a tenth of a millimetre. */
    static final int METRE_DECIMALS = 4;

    static String metres(double v) {
        return fixed(v, METRE_DECIMALS);
    }

    /** A heading in radians: a millionth is 5 µm over a car's length. */
    static String angle(double v) {
        return fixed(v, 6);
    }

    /** A time in seconds: every time sitcov exports is a whole number of 0.2 s ticks. */
    static String seconds(double v) {
        return fixed(v, 1);
    }

    /** A curvature: to a billionth. */
    static String fine(double v) {
        return fixed(v, 9);
    }

    static String fixed(double v, int decimals) {
        String s = String.format(Locale.ROOT, "%." + decimals + "f", v);
        // no "-0.0000": the same value always reads the same
        return s.charAt(0) == '-' && Double.parseDouble(s) == 0 ? s.substring(1) : s;
    }

    /**
     * A number given as a whole count of units of {@code 10^-decimals}, written exactly and as short as
     * it reads: trailing zeros and a bare point dropped ({@code 34913, 3} is "34.913", {@code -600, 3} is
     * "-0.6", {@code 0, 3} is "0").
     */
    static String decimal(long units, int decimals) {
        long scale = 1;
        for (int i = 0; i < decimals; i++) {
            scale *= 10;
        }
        long magnitude = Math.abs(units);
        StringBuilder s = new StringBuilder(16);
        if (units < 0) {
            s.append('-');
        }
        s.append(magnitude / scale);
        long fraction = magnitude % scale;
        if (fraction != 0) {
            int digits = decimals;
            while (fraction % 10 == 0) {
                fraction /= 10;
                digits--;
            }
            String f = Long.toString(fraction);
            s.append('.').append("0".repeat(digits - f.length())).append(f);
        }
        return s.toString();
    }

    static String integer(long v) {
        return Long.toString(v);
    }
}
