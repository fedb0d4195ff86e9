package sitcov;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/** What the documentation tests read in Markdown: headings and their anchors, links, fenced blocks. */
public final class Markdown {
    private static final Pattern HEADING = Pattern.compile("^#{1,6} +(.+?) *#* *$");
    private static final Pattern FENCE = Pattern.compile("^(```|~~~)");
    private static final Pattern CODE_SPAN = Pattern.compile("(`+)(?:(?!\\1).)+?\\1");
    private static final Pattern COMMENT_CONTINUATION = Pattern.compile("[ \\t]*\\R[ \\t]*(?:\\*(?!/)|//|#)?[ \\t]*");

    private Markdown() {
    }

    /** The text of each heading of a Markdown file outside fenced blocks, as written and without its code marks. */
    public static Set<String> headings(Path file) {
        Set<String> headings = new LinkedHashSet<>();
        for (String line : outsideFences(read(file))) {
            Matcher m = HEADING.matcher(line);
            if (m.matches()) {
                headings.add(m.group(1));
                headings.add(m.group(1).replace("`", ""));
            }
        }
        return headings;
    }

    /** The anchors GitHub gives a file's headings: duplicates numbered -1, -2, … in order. */
    public static Set<String> anchors(Path file) {
        Set<String> anchors = new LinkedHashSet<>();
        Map<String, Integer> seen = new HashMap<>();
        for (String line : outsideFences(read(file))) {
            Matcher m = HEADING.matcher(line);
            if (m.matches()) {
                String anchor = anchor(m.group(1));
                int n = seen.merge(anchor, 1, Integer::sum) - 1;
                anchors.add(n == 0 ? anchor : anchor + "-" + n);
            }
        }
        return anchors;
    }

    /** GitHub's anchor of a heading: lower case, letters, digits, '-' and '_' kept, spaces to '-', the rest dropped. */
    public static String anchor(String heading) {
        StringBuilder b = new StringBuilder();
        heading.strip().toLowerCase(Locale.ROOT).codePoints().forEach(c -> {
            if (Character.isLetterOrDigit(c) || c == '-' || c == '_') {
                b.appendCodePoint(c);
            } else if (c == ' ') {
                b.append('-');
            }
        });
        return b.toString();
    }

    /**
     * Why a link from {@code doc} to {@code target} does not resolve, or null when it does. Links with a scheme
     * (https:, mailto:) are not checked: they leave the repository.
     */
    public static String resolve(Path doc, String target) {
        if (target.matches("^[a-zA-Z][a-zA-Z0-9+.-]*:.*")) {
            return null;
        }
        int hash = target.indexOf('#');
        String file = hash < 0 ? target : target.substring(0, hash);
        Path resolved = file.isEmpty() ? doc : doc.getParent().resolve(file).normalize();
        if (!Files.exists(resolved)) {
            return "no such file: " + resolved;
        }
        if (hash < 0) {
            return null;
        }
        String anchor = target.substring(hash + 1);
        if (!resolved.toString().endsWith(".md")) {
            return "an anchor into a file that is not Markdown";
        }
        return anchors(resolved).contains(anchor) ? null : "no heading of " + resolved.getFileName() + " has the anchor #" + anchor;
    }

    /** The lines of a Markdown text outside fenced blocks. */
    public static List<String> outsideFences(String markdown) {
        List<String> lines = new ArrayList<>();
        boolean fenced = false;
        for (String line : markdown.split("\\R", -1)) {
            if (FENCE.matcher(line).find()) {
                fenced = !fenced;
            } else if (!fenced) {
                lines.add(line);
            }
        }
        return lines;
    }

    /** The prose of a Markdown text: outside fenced blocks, with code spans left out. */
    public static String prose(String markdown) {
        return CODE_SPAN.matcher(String.join("\n", outsideFences(markdown))).replaceAll("");
    }

    /** A text with its line breaks, and the comment marks that open continuation lines, joined into spaces. */
    public static String joinCommentLines(String text) {
        return COMMENT_CONTINUATION.matcher(text).replaceAll(" ");
    }

    static String read(Path file) {
        try {
            return Files.readString(file, StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
