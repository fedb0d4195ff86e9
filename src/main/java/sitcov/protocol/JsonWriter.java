package sitcov.protocol;

/**
 * Writes one JSON value at a time into a reused buffer: objects, arrays, strings, numbers,
 * booleans and null. Doubles are written in Java's round-trip form ({@link Double#toString}), so
 * a reader that parses them as doubles gets the same bits; NaN is written as null and the
 * infinities as ±1e999 (which every JSON reader parses back to an infinity). Commas are placed for
 * the caller. Not thread-safe; {@link #reset} starts the next message in the same buffer.
 */
final class JsonWriter {
    private static final int MAX_DEPTH = 32;

    private final StringBuilder out = new StringBuilder(4096);
    /** Per open object or array: whether the next member needs a comma before it. */
    private final boolean[] needsComma = new boolean[MAX_DEPTH];
    private int depth;
    /** After a member's name, its value follows without a comma. */
    private boolean afterName;

    /** Empties the buffer for the next message. */
    JsonWriter reset() {
        out.setLength(0);
        depth = 0;
        afterName = false;
        return this;
    }

    /** The text written since the last {@link #reset}. */
    CharSequence text() {
        return out;
    }

    JsonWriter beginObject() {
        separate();
        out.append('{');
        needsComma[++depth] = false;
        return this;
    }

    JsonWriter endObject() {
        out.append('}');
        depth--;
        return this;
    }

    JsonWriter beginArray() {
        separate();
        out.append('[');
        needsComma[++depth] = false;
        return this;
    }

    JsonWriter endArray() {
        out.append(']');
        depth--;
        return this;
    }

    /** A member's name; its value comes next. */
    JsonWriter name(String name) {
        separate();
        string(name);
        out.append(':');
        afterName = true;
        return this;
    }

    JsonWriter value(double d) {
        separate();
        if (Double.isNaN(d)) {
            out.append("null");
        } else if (Double.isInfinite(d)) {
            out.append(d > 0 ? "1e999" : "-1e999");
        } else if (d == Math.rint(d) && Math.abs(d) < 1e15) {
            // whole numbers as integers ("3", not "3.0"): shorter, and parsed back to the same double
            out.append((long) d);
            if (d == 0 && 1 / d < 0) {
                out.setLength(out.length() - 1);
                out.append("-0.0");
            }
        } else {
            out.append(d);
        }
        return this;
    }

    JsonWriter value(long n) {
        separate();
        out.append(n);
        return this;
    }

    JsonWriter value(boolean b) {
        separate();
        out.append(b);
        return this;
    }

    /** A string, or null for null. */
    JsonWriter value(String s) {
        separate();
        if (s == null) {
            out.append("null");
        } else {
            string(s);
        }
        return this;
    }

    JsonWriter nullValue() {
        separate();
        out.append("null");
        return this;
    }

    JsonWriter member(String name, double d) {
        return name(name).value(d);
    }

    JsonWriter member(String name, long n) {
        return name(name).value(n);
    }

    JsonWriter member(String name, boolean b) {
        return name(name).value(b);
    }

    JsonWriter member(String name, String s) {
        return name(name).value(s);
    }

    private void separate() {
        if (afterName) {
            afterName = false;
            return;
        }
        if (depth > 0) {
            if (needsComma[depth]) {
                out.append(',');
            }
            needsComma[depth] = true;
        }
    }

    private void string(String s) {
        out.append('"');
        if (isPlain(s)) {
            // names and most values need no escape: one copy instead of a char at a time
            out.append(s).append('"');
            return;
        }
        for (int i = 0, n = s.length(); i < n; i++) {
            char c = s.charAt(i);
            switch (c) {
                case '"' -> out.append("\\\"");
                case '\\' -> out.append("\\\\");
                case '\n' -> out.append("\\n");
                case '\r' -> out.append("\\r");
                case '\t' -> out.append("\\t");
                default -> {
                    if (c < 0x20 || c == 0x2028 || c == 0x2029) {
                        out.append(String.format("\\u%04x", (int) c));
                    } else {
                        out.append(c);
                    }
                }
            }
        }
        out.append('"');
    }

    /** Whether {@code s} is written as it stands between quotes: printable ASCII, no quote or backslash. */
    private static boolean isPlain(String s) {
        for (int i = 0, n = s.length(); i < n; i++) {
            char c = s.charAt(i);
            if (c < 0x20 || c >= 0x7f || c == '"' || c == '\\') {
                return false;
            }
        }
        return true;
    }
}
