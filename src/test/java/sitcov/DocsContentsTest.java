package sitcov;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * Every reference page of more than a couple of sections opens with a table of contents that lists its sections and
 * their subsections, in order: a reader finds the section before scrolling for it.
 */
class DocsContentsTest {
    private static final Path ROOT = Path.of("").toAbsolutePath();
    private static final Pattern HEADING = Pattern.compile("^(#{1,6}) +(.+?) *#* *$");
    private static final Pattern ENTRY = Pattern.compile("^( *)- \\[.*\\]\\(#([^)]+)\\)$");
    private static final String OPEN = "<!-- toc -->";
    private static final String CLOSE = "<!-- /toc -->";

    @Test
    void everyPageOfThreeOrMoreSectionsListsEachOfThemInItsContents() throws IOException {
        List<Path> pages;
        try (Stream<Path> s = Files.walk(ROOT)) {
            pages = s.filter(p -> p.toString().endsWith(".md") && !ROOT.relativize(p).startsWith("target")
                    && !p.toString().contains("/target/") && !p.toString().contains("/.git/")
                    && !p.equals(ROOT.resolve("README.md"))).sorted().toList();
        }
        int checked = 0;
        for (Path page : pages) {
            List<String> sections = sections(page);
            if (sections.stream().filter(s -> !s.startsWith("  ")).count() < 3) {
                continue;
            }
            checked++;
            String text = Files.readString(page);
            int open = text.indexOf(OPEN);
            int close = text.indexOf(CLOSE);
            assertTrue(open >= 0 && close > open, ROOT.relativize(page) + " has " + sections.size() + " sections but no "
                    + OPEN + " … " + CLOSE + " contents listing them");
            List<String> listed = new ArrayList<>();
            for (String line : text.substring(open, close).split("\n")) {
                Matcher m = ENTRY.matcher(line);
                if (m.matches()) {
                    listed.add(m.group(1) + m.group(2));
                }
            }
            assertEquals(sections, listed, "the contents of " + ROOT.relativize(page) + " (two spaces indent a subsection)");
        }
        assertTrue(checked >= 10, "the reference pages checked: " + checked);
    }

    /** Each section's and subsection's anchor, in order, a subsection's indented by two spaces. */
    private static List<String> sections(Path page) {
        List<String> sections = new ArrayList<>();
        Map<String, Integer> seen = new HashMap<>();
        for (String line : Markdown.outsideFences(Markdown.read(page))) {
            Matcher h = HEADING.matcher(line);
            if (!h.matches()) {
                continue;
            }
            String anchor = Markdown.anchor(h.group(2));
            int n = seen.merge(anchor, 1, Integer::sum) - 1;
            anchor = n == 0 ? anchor : anchor + "-" + n;
            int level = h.group(1).length();
            if (level == 2 || level == 3) {
                sections.add((level == 3 ? "  " : "") + anchor);
            }
        }
        return sections;
    }
}
