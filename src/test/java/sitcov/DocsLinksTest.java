package sitcov;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.FileVisitResult;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.SimpleFileVisitor;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * The documentation holds together: every relative link of every Markdown file resolves (to a file, and with a
 * {@code #anchor} to one of its headings), and every citation of a heading such as {@code faults/README.md, "The
 * catalogue"} in the
 * code, presets, scripts and docs, names a heading of that file (src/README.md, "Checks on the documentation").
 */
class DocsLinksTest {
    private static final Path ROOT = Path.of("").toAbsolutePath();
    private static final Pattern LINK = Pattern.compile("!?\\[[^\\]]*\\]\\(([^)\\s]+)\\)");
    /** A citation: a path ending in .md, then one or more quoted headings ("…" or '…'), joined by commas. */
    private static final Pattern CITATION = Pattern.compile(
            "([\\w./-]+\\.md),((?:\\s*(?:and\\s+)?([\"'])[^\"'\\n]+?\\3,?)+)");
    private static final Pattern QUOTED = Pattern.compile("([\"'])([^\"'\\n]+?)\\1");
    /** An old-style citation that names no file. */
    private static final Pattern BARE = Pattern.compile("(?<![\\w/.])README(?!\\.md)\\s*[,:]\\s*[\"']");

    @Test
    void everyRelativeLinkOfEveryMarkdownFileResolves() throws IOException {
        List<String> broken = new ArrayList<>();
        List<Path> docs = files(".md");
        assertTrue(docs.size() >= 10, "the Markdown files: " + docs);
        for (Path doc : docs) {
            for (String target : links(Files.readString(doc, StandardCharsets.UTF_8))) {
                String problem = Markdown.resolve(doc, target);
                if (problem != null) {
                    broken.add(ROOT.relativize(doc) + ": (" + target + ") " + problem);
                }
            }
        }
        assertEquals(List.of(), broken, "links that do not resolve");
    }

    @Test
    void everyCitedHeadingExistsInTheCitedFile() throws IOException {
        List<String> broken = new ArrayList<>();
        int citations = 0;
        for (Path file : files(".java", ".properties", ".py", ".sh", ".sbatch", ".json", ".md", "run",
                "fetch-asam-schemas", "fetch-jsonschema")) {
            String text = Markdown.joinCommentLines(Files.readString(file, StandardCharsets.UTF_8));
            Matcher m = CITATION.matcher(text);
            while (m.find()) {
                Path cited = ROOT.resolve(m.group(1)).normalize();
                if (!Files.isRegularFile(cited)) {
                    cited = file.getParent().resolve(m.group(1)).normalize();
                }
                Matcher q = QUOTED.matcher(m.group(2));
                while (q.find()) {
                    citations++;
                    String heading = q.group(2);
                    if (!Files.isRegularFile(cited)) {
                        broken.add(ROOT.relativize(file) + ": cites " + m.group(1) + ", which is not a file");
                    } else if (!Markdown.headings(cited).contains(heading)) {
                        broken.add(ROOT.relativize(file) + ": cites " + m.group(1) + ", \"" + heading
                                + "\", which is not one of its headings");
                    }
                }
            }
            Matcher bare = BARE.matcher(text);
            while (bare.find()) {
                broken.add(ROOT.relativize(file) + ": cites the README without its path: "
                        + text.substring(bare.start(), Math.min(text.length(), bare.end() + 40)));
            }
        }
        assertTrue(citations > 50, "the citations found: " + citations);
        assertEquals(List.of(), broken, "citations that do not resolve");
    }

    @Test
    void aHeadingsAnchorIsGitHubs() {
        assertEquals("the-papers-experiment-on-your-controller-byo-rq1",
                Markdown.anchor("The paper's experiment on your controller (`byo-rq1`)"));
        assertEquals("campaigns-falsifying-one-version", Markdown.anchor("Campaigns: falsifying one version"));
        assertEquals("0--stale-waypoint-identity", Markdown.anchor("0 · stale-waypoint-identity"));
    }

    /** The link targets of a Markdown text, outside fenced blocks and code spans. */
    private static List<String> links(String markdown) {
        List<String> targets = new ArrayList<>();
        Matcher m = LINK.matcher(Markdown.prose(markdown));
        while (m.find()) {
            targets.add(m.group(1));
        }
        return targets;
    }

    /** The repository's files with one of these endings, outside build output (target/) and git's own files. */
    private static List<Path> files(String... endings) throws IOException {
        List<Path> files = new ArrayList<>();
        Files.walkFileTree(ROOT, new SimpleFileVisitor<>() {
            @Override
            public FileVisitResult preVisitDirectory(Path d, BasicFileAttributes attrs) {
                String name = d.getFileName() == null ? "" : d.getFileName().toString();
                return name.equals("target") || name.equals(".git") ? FileVisitResult.SKIP_SUBTREE : FileVisitResult.CONTINUE;
            }

            @Override
            public FileVisitResult visitFile(Path f, BasicFileAttributes attrs) {
                String name = f.getFileName().toString();
                if (attrs.isRegularFile() && Stream.of(endings).anyMatch(name::endsWith)) {
                    files.add(f);
                }
                return FileVisitResult.CONTINUE;
            }
        });
        files.sort(null);
        return files;
    }
}
