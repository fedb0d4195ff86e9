package sitcov.results;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

/**
 * The {@code checks} line of a folder's properties file ({@code manifest.properties}, a campaign's
 * {@code campaign.properties}): a CRC-32 of every other line but {@code complete}, the one line the
 * tool itself flips. A hand edit is refused naming the key changed, added or removed
 * (experiments/README.md, "Guarded against hand edits").
 */
public final class ManifestChecks {
    public static final String CHECKS = "checks";
    static final String COMPLETE = "complete";

    private ManifestChecks() {
    }

    /** The file's lines: {@code header}, then every key in order, the checks among them when {@code checked}. */
    static List<String> lines(String header, Map<String, String> keys, boolean checked, boolean complete) {
        Map<String, String> m = new TreeMap<>(keys);
        if (checked) {
            List<String> crcs = new ArrayList<>();
            m.forEach((k, v) -> crcs.add(JournalCheck.crc(k + "=" + v)));
            m.put(CHECKS, String.join(" ", crcs));
        }
        m.put(COMPLETE, Boolean.toString(complete));
        List<String> rows = new ArrayList<>();
        rows.add(header);
        m.forEach((k, v) -> rows.add(k + "=" + v));
        return rows;
    }

    /**
     * {@code lines} (each {@code key=value}, in the file's own order) followed by their checks and {@code complete}:
     * for a properties file whose order is its own, as an estimate's manifest is.
     */
    public static List<String> inOrder(List<String> lines, boolean complete) {
        List<String> rows = new ArrayList<>(lines);
        rows.add(CHECKS + "=" + String.join(" ", lines.stream().map(JournalCheck::crc).toList()));
        rows.add(COMPLETE + "=" + complete);
        return rows;
    }

    /**
     * Refuses a file whose lines are not those its checks were made of, naming the keys that were
     * changed, added or removed.
     *
     * @param fix what the user can do, ending the message
     */
    public static void verify(String text, Path file, String fix) {
        List<String> lines = new ArrayList<>();
        String checks = "";
        for (String line : text.split("\n", -1)) {
            String key = key(line);
            if (key.equals(CHECKS)) {
                checks = line.substring(line.indexOf('=') + 1).strip();
            } else if (!key.isEmpty() && !key.equals(COMPLETE)) {
                lines.add(line);
            }
        }
        List<String> stored = checks.isEmpty() ? List.of() : List.of(checks.split(" +"));
        List<String> changed = new ArrayList<>();
        if (stored.size() == lines.size()) {
            for (int i = 0; i < lines.size(); i++) {
                if (!JournalCheck.crc(lines.get(i)).equals(stored.get(i))) {
                    changed.add(key(lines.get(i)));
                }
            }
        } else {
            lines.stream().filter(l -> !stored.contains(JournalCheck.crc(l))).forEach(l -> changed.add(key(l)));
        }
        if (changed.isEmpty() && stored.size() == lines.size()) {
            return;
        }
        String what = changed.isEmpty() ? removed(lines, stored) : String.join(", ", changed) + (changed.size() == 1
                ? " was" : " were") + (stored.size() == lines.size() ? " changed" : " added or changed");
        throw new IllegalArgumentException(file + ": " + what + " after sitcov wrote it (the '" + CHECKS
                + "' line no longer matches); " + fix);
    }

    /** Where lines are missing: before the first line that is out of step with the checks. */
    private static String removed(List<String> lines, List<String> stored) {
        if (lines.size() > stored.size()) {
            return "a line was repeated";
        }
        for (int i = 0; i < lines.size(); i++) {
            if (!JournalCheck.crc(lines.get(i)).equals(stored.get(i))) {
                return "a line before '" + key(lines.get(i)) + "' was removed";
            }
        }
        return lines.isEmpty() ? "its lines were removed" : "a line after '" + key(lines.get(lines.size() - 1)) + "' was removed";
    }

    /** The key of a properties line; empty for a comment or a blank line. */
    private static String key(String line) {
        String s = line.strip();
        if (s.isEmpty() || s.startsWith("#") || s.startsWith("!")) {
            return "";
        }
        int eq = s.indexOf('=');
        return (eq < 0 ? s : s.substring(0, eq)).strip();
    }
}
