package sitcov.protocol;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.util.Arrays;

/**
 * JSON Lines over a pair of byte streams, UTF-8: reads one line at a time (without its newline),
 * writes one message and its newline and flushes. Reads and writes go through reused buffers.
 */
final class Lines {
    /** A longer line is not a message: a controller stuck in a loop printing, say. */
    static final int MAX_LINE = 64 << 20;

    private final InputStream in;
    private final OutputStream out;
    /**
     * 8 KB: the JDK reads a pipe into a stack buffer of that size, and mallocs (and frees) one for
     * every larger read, which cost more than the rest of a tick's protocol work together.
     */
    private final byte[] inBuffer = new byte[8192];
    private int inStart;
    private int inEnd;
    private byte[] line = new byte[1 << 12];
    private byte[] outBuffer = new byte[1 << 12];

    Lines(InputStream in, OutputStream out) {
        this.in = in;
        this.out = out;
    }

    /** The next line, or null at the end of the input. */
    String read() throws IOException {
        int length = 0;
        while (true) {
            if (inStart == inEnd) {
                int n = in.read(inBuffer, 0, inBuffer.length);
                if (n < 0) {
                    return length == 0 ? null : decode(length);
                }
                inStart = 0;
                inEnd = n;
            }
            int newline = -1;
            for (int i = inStart; i < inEnd; i++) {
                if (inBuffer[i] == '\n') {
                    newline = i;
                    break;
                }
            }
            int end = newline < 0 ? inEnd : newline;
            int take = end - inStart;
            if (length + take > MAX_LINE) {
                throw new IOException("a line longer than " + (MAX_LINE >> 20) + " MB");
            }
            if (length + take > line.length) {
                line = Arrays.copyOf(line, Math.max(2 * line.length, length + take));
            }
            System.arraycopy(inBuffer, inStart, line, length, take);
            length += take;
            inStart = end;
            if (newline >= 0) {
                inStart++;
                return decode(length);
            }
        }
    }

    private String decode(int length) {
        if (length > 0 && line[length - 1] == '\r') {
            length--;
        }
        return new String(line, 0, length, StandardCharsets.UTF_8);
    }

    /** Writes the message {@code w} holds, a newline, and flushes. */
    void write(JsonWriter w) throws IOException {
        CharSequence text = w.text();
        int n = text.length();
        if (outBuffer.length < n + 1) {
            outBuffer = new byte[Math.max(2 * outBuffer.length, n + 1)];
        }
        for (int i = 0; i < n; i++) {
            char c = text.charAt(i);
            if (c >= 0x80) {
                // rare (a name or an outcome with non-ASCII text): encode the whole message properly
                byte[] utf8 = (text + "\n").getBytes(StandardCharsets.UTF_8);
                out.write(utf8);
                out.flush();
                return;
            }
            outBuffer[i] = (byte) c;
        }
        outBuffer[n] = '\n';
        out.write(outBuffer, 0, n + 1);
        out.flush();
    }

    void closeOutput() throws IOException {
        out.close();
    }
}
