package sitcov.results;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.List;
import java.util.zip.CRC32;

/**
 * The checks that make a results folder refuse hand edits (experiments/README.md, "The results folder"): every
 * row of the journal files ends in a {@code check} column, a CRC-32 of the row keyed by the
 * experiment's identity, so a row is valid only as written and only under the manifest it was
 * written for; runs.csv rows also carry {@code situation_check}, the CRC-32 of the kept situation
 * file of their map. A folder written before checks existed is read and written as it is
 * ({@link #NONE}).
 */
public final class JournalCheck {
    static final String CHECK = "check";
    static final String SITUATION_CHECK = "situation_check";
    static final JournalCheck NONE = new JournalCheck(null);

    /** Null for a folder written before checks. */
    private final byte[] key;

    private JournalCheck(byte[] key) {
        this.key = key;
    }

    public static JournalCheck of(Manifest manifest) {
        return manifest.checked()
                ? new JournalCheck(manifest.experimentDigest().getBytes(StandardCharsets.UTF_8)) : NONE;
    }

    boolean active() {
        return key != null;
    }

    /** CRC-32 of the parts' UTF-8 bytes, as 8 hex digits. */
    static String crc(byte[]... parts) {
        CRC32 crc = new CRC32();
        for (byte[] p : parts) {
            crc.update(p);
        }
        return HexFormat.of().toHexDigits((int) crc.getValue());
    }

    static String crc(String text) {
        return crc(text.getBytes(StandardCharsets.UTF_8));
    }

    /** The header of a journal file, with the check columns it carries. */
    public String header(String plain, boolean runs) {
        if (!active()) {
            return plain;
        }
        return plain + (runs ? "," + SITUATION_CHECK : "") + "," + CHECK;
    }

    /** Rows (each ending in '\n') with their check; runs.csv rows get the map's situation check first. */
    String rows(String plain, String situationCheck) {
        if (!active()) {
            return plain;
        }
        StringBuilder out = new StringBuilder(plain.length() + 32);
        int start = 0;
        for (int nl = plain.indexOf('\n'); nl >= 0; nl = plain.indexOf('\n', start)) {
            String row = plain.substring(start, nl) + (situationCheck == null ? "" : "," + situationCheck);
            out.append(row).append(',').append(sign(row)).append('\n');
            start = nl + 1;
        }
        return out.toString();
    }

    String rows(String plain) {
        return rows(plain, null);
    }

    private String sign(String row) {
        return crc(key, row.getBytes(StandardCharsets.UTF_8));
    }

    /** A journal file's whole lines, checked: the rows without their check columns, and each row's situation check. */
    record Checked(List<String> lines, List<String> situationChecks) {
    }

    /**
     * Checks every row of a journal file's whole lines (the header is compared by its reader) and
     * takes the check columns off.
     *
     * @throws IllegalArgumentException naming the file's line that was changed
     */
    Checked read(List<String> lines, String source, boolean runs, String fix) {
        if (!active() || lines.isEmpty()) {
            return new Checked(lines, List.of());
        }
        List<String> plain = new ArrayList<>(lines.size());
        List<String> situations = new ArrayList<>(runs ? lines.size() : 0);
        plain.add(stripHeader(lines.get(0), runs, source, fix));
        for (int i = 1; i < lines.size(); i++) {
            String line = lines.get(i);
            int cut = line.lastIndexOf(',');
            if (cut < 0 || !line.substring(cut + 1).equals(sign(line.substring(0, cut)))) {
                throw new IllegalArgumentException(source + ":" + (i + 1) + ": this row was changed after sitcov wrote it"
                        + (noneMatches(lines) ? " (no row matches this manifest: the journal or the manifest was replaced)"
                        : " (it does not match its check)") + "; " + fix);
            }
            String row = line.substring(0, cut);
            if (runs) {
                int at = row.lastIndexOf(',');
                situations.add(row.substring(at + 1));
                row = row.substring(0, at);
            }
            plain.add(row);
        }
        return new Checked(plain, situations);
    }

    private static String stripHeader(String header, boolean runs, String source, String fix) {
        String tail = (runs ? "," + SITUATION_CHECK : "") + "," + CHECK;
        if (!header.endsWith(tail)) {
            throw new IllegalArgumentException(source + ":1: the header lacks the columns '" + tail.substring(1)
                    + "' that the folder's manifest promises: the file was changed after sitcov wrote it; " + fix);
        }
        return header.substring(0, header.length() - tail.length());
    }

    private boolean noneMatches(List<String> lines) {
        for (int i = 1; i < lines.size(); i++) {
            String line = lines.get(i);
            int cut = line.lastIndexOf(',');
            if (cut >= 0 && line.substring(cut + 1).equals(sign(line.substring(0, cut)))) {
                return false;
            }
        }
        return lines.size() > 2;
    }
}
