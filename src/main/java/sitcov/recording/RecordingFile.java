package sitcov.recording;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.HexFormat;
import java.util.zip.CRC32;
import java.util.zip.GZIPInputStream;
import java.util.zip.GZIPOutputStream;
import java.util.zip.ZipException;

/**
 * A recording's file: gzip-compressed JSON Lines (RECORDINGS.md). A header line names the run, one
 * line a tick holds its command after clamping ({@code v} speed in metres a tick, {@code s} steering
 * in degrees; {@code asked} where the world clamped, {@code release}/{@code claim} junctions, a
 * {@code report} where the self-report changed) or the controller's failure, and the last line the
 * CRC-32 of everything before it: a recording is valid only as written. The header names the run and
 * its seeds, so a recording put in another's place is refused too. The same run gives the same bytes.
 */
public final class RecordingFile {
    public static final String SUFFIX = ".jsonl.gz";
    static final int FORMAT = 1;

    private RecordingFile() {
    }

    /** The file's bytes. */
    public static byte[] write(Recording r) {
        String text = RecordingText.format(r);
        String sealed = text + "{\"crc\":\"" + crc(text.getBytes(StandardCharsets.UTF_8)) + "\"}\n";
        ByteArrayOutputStream bytes = new ByteArrayOutputStream(text.length() / 4 + 64);
        try (GZIPOutputStream gzip = new GZIPOutputStream(bytes)) {
            gzip.write(sealed.getBytes(StandardCharsets.UTF_8));
        } catch (IOException e) {
            throw new UncheckedIOException(e); // in memory: cannot happen
        }
        return bytes.toByteArray();
    }

    /**
     * The recording in {@code file}, its check verified.
     *
     * @throws IllegalArgumentException naming the file, when it is missing, not a recording, or was changed
     */
    public static Recording read(Path file) throws IOException {
        String text;
        try (InputStream in = new GZIPInputStream(Files.newInputStream(file))) {
            text = new String(in.readAllBytes(), StandardCharsets.UTF_8);
        } catch (NoSuchFileException e) {
            throw new IllegalArgumentException("the recording " + file + " is missing");
        } catch (ZipException | java.io.EOFException e) {
            throw new IllegalArgumentException("the recording " + file + " is not a gzip file sitcov wrote whole ("
                    + e.getMessage() + ")");
        }
        int last = text.lastIndexOf("{\"crc\":\"");
        String body = last < 0 ? text : text.substring(0, last);
        String expected = "{\"crc\":\"" + crc(body.getBytes(StandardCharsets.UTF_8)) + "\"}\n";
        if (last < 0 || !text.substring(last).equals(expected)) {
            throw new IllegalArgumentException("the recording " + file + " was changed after sitcov wrote it (its check"
                    + " does not match)");
        }
        return RecordingText.parse(body, file.toString());
    }

    static String crc(byte[] content) {
        CRC32 crc = new CRC32();
        crc.update(content);
        return HexFormat.of().toHexDigits((int) crc.getValue());
    }

}
