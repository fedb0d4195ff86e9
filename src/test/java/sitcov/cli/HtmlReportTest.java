package sitcov.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import sitcov.results.ResultsFolder;

/** The report.html of a results folder, read as a browser would: what it links to must be there. */
class HtmlReportTest {
    private static final Pattern LINK = Pattern.compile("(?:href|src)=\"([^\"]*)\"");

    @Test
    void everyLinkAndImageOfTheReportNamesAFileOfTheFolder() throws Exception {
        Path folder = ResultsFolders.tinyReference();
        String html = Files.readString(folder.resolve(ResultsFolder.REPORT));
        List<String> targets = new ArrayList<>();
        Matcher m = LINK.matcher(html);
        while (m.find()) {
            targets.add(m.group(1));
        }
        assertTrue(targets.contains(ResultsFolder.forestPlot(1, "coverage-filter", "random")) && targets.contains(ResultsFolder.STATS), targets.toString());
        for (String t : targets) {
            assertFalse(t.startsWith("http") || t.startsWith("//") || t.startsWith("/"), "nothing fetched from outside: " + t);
            assertTrue(Files.isRegularFile(folder.resolve(t)), "the report names " + t + ", which the folder lacks");
        }
    }

    @Test
    void theReportShowsEachVerdictLineAsHeadingBottomLineItemOrParagraph() throws Exception {
        Path folder = ResultsFolders.tinyReference();
        String html = Files.readString(folder.resolve(ResultsFolder.REPORT));
        List<String> verdict = Files.readAllLines(folder.resolve(ResultsFolder.VERDICT));
        assertTrue(verdict.stream().anyMatch(l -> l.startsWith("## coverage-filter against random")), verdict.toString());
        for (String line : verdict) {
            String shown = esc(line.replaceFirst("^(- |## )", ""));
            String expected = line.startsWith("- ") ? "<li>" + shown + "</li>" : line.startsWith("## ") ? "<h3>" + shown
                    + "</h3>" : line.startsWith("In short: ") ? "<p><strong>" + shown + "</strong></p>" : "<p>" + shown + "</p>";
            assertTrue(html.contains(expected), "verdict line missing: " + line);
        }
        assertEquals(html.indexOf("<script"), -1, "no script");
    }

    @Test
    void everyTableFitsAPrintedPageAndLabelsItsCellsForANarrowScreen() throws Exception {
        String html = Files.readString(ResultsFolders.tinyReference().resolve(ResultsFolder.REPORT));
        Matcher table = Pattern.compile("<table class=\"stack\">(.*?)</table>", Pattern.DOTALL).matcher(html);
        int tables = 0;
        while (table.find()) {
            tables++;
            String t = table.group(1);
            int headings = t.substring(0, t.indexOf("</thead>")).split("<th[ >]", -1).length - 1;
            assertTrue(headings <= 9, headings + " columns do not fit a printed page: " + t.substring(0, 300));
            int cells = t.split("<td", -1).length - 1;
            assertEquals(cells, t.split("<td[^>]*data-label=", -1).length - 1, "a cell without its column's label");
        }
        assertTrue(tables >= 6, "measures, replications, two per pair, Table 2, uniformity: " + tables);
    }

    @Test
    void numbersAreWrittenForPeopleNotAsTheCsvHoldsThem() throws Exception {
        Path folder = ResultsFolders.tinyReference();
        String html = Files.readString(folder.resolve(ResultsFolder.REPORT));
        assertTrue(Files.readString(folder.resolve(ResultsFolder.STATS)).matches("(?s).*\\d\\.\\d{5}.*"),
                "the CSV holds long decimals, so this test could fail");
        Matcher cell = Pattern.compile("<td[^>]*>([^<]*)</td>").matcher(html);
        int cells = 0;
        while (cell.find()) {
            cells++;
            assertFalse(cell.group(1).matches(".*\\d\\.\\d{4,}.*"), "too many places: " + cell.group(1));
        }
        assertTrue(cells > 50, "cells read: " + cells);
    }

    @Test
    void theSummaryIsFoldedBelowMeansOneRowPerReplicationAndNotion() throws Exception {
        Path folder = ResultsFolders.tinyReference();
        String html = Files.readString(folder.resolve(ResultsFolder.REPORT));
        long summaryRows = Files.readAllLines(folder.resolve(ResultsFolder.SUMMARY)).size() - 1;
        int start = html.indexOf("<details>");
        int end = html.indexOf("</details>", start);
        assertEquals(summaryRows, html.substring(start, end).split("<tr>", -1).length - 2, "a row per CSV row, and the heading");
    }

    @Test
    void eachReplayCommandRunsAsPrintedFromTheFolderIntoItsOwnPicture(@TempDir Path out) throws Exception {
        Path folder = ResultsFolders.tinyReference();
        String html = Files.readString(folder.resolve(ResultsFolder.REPORT));
        Matcher cmd = Pattern.compile("<code class=\"cmd\">(.*?)</code>").matcher(html);
        List<String> replays = new ArrayList<>();
        while (cmd.find()) {
            String text = cmd.group(1).replaceAll("</?span>", "").replace("&quot;", "\"").replace("&amp;", "&");
            if (text.startsWith("java -jar \"$SITCOV_JAR\" replay . --row ")) {
                replays.add(text);
            }
        }
        assertTrue(replays.size() >= 2, replays.toString());
        assertEquals(replays.size(), replays.stream().map(r -> r.substring(r.lastIndexOf(' '))).distinct().count(),
                "each row writes a picture of its own: " + replays);
        String[] words = replays.get(0).split(" ");
        List<String> args = new ArrayList<>(List.of(words).subList(3, words.length));
        args.set(1, folder.toString());
        args.set(args.size() - 1, out.resolve(words[words.length - 1]).toString());
        CliRunner r = CliRunner.run(args.toArray(String[]::new));
        assertEquals(0, r.exitCode(), r.err());
        assertTrue(Files.size(out.resolve(words[words.length - 1])) > 0);
    }

    private static String esc(String s) {
        return s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;").replace("\"", "&quot;");
    }

    @Test
    void aFolderWithManyFindingsPicturesItsFirst24AndSaysHowToDrawTheRest() throws Exception {
        Path folder = ResultsFolders.tinyReference();
        // the failures and findings by kind, read from runs.csv: the reference's own failures, then each fault's findings
        List<String> rows = Files.readAllLines(folder.resolve(ResultsFolder.RUNS));
        List<String> header = List.of(rows.get(0).split(","));
        java.util.Map<String, List<Integer>> kinds = new java.util.LinkedHashMap<>();
        kinds.put("own", new ArrayList<>());
        for (int n = 1; n < rows.size(); n++) {
            String[] cells = rows.get(n).split(",", -1);
            String fault = cells[header.indexOf("fault")];
            boolean accident = java.util.stream.Stream.of("clashwithobstacle", "clashwithothercar", "leaveroad",
                    "crosscentreline", "timeout").anyMatch(c -> !cells[header.indexOf(c)].equals("0"));
            if (fault.equals("NONE") && accident) {
                kinds.get("own").add(n);
            } else if (cells[header.indexOf("detection")].equals("FOUND")) {
                kinds.computeIfAbsent(fault, f -> new ArrayList<>()).add(n);
            }
        }
        int all = kinds.values().stream().mapToInt(List::size).sum();
        assertTrue(all > 24, "the case this test needs: more failures and findings than are drawn, " + kinds);
        String html = Files.readString(folder.resolve(ResultsFolder.REPORT));
        java.util.Set<Integer> drawn = new java.util.HashSet<>();
        Matcher img = Pattern.compile("<img loading=\"lazy\" src=\"replays/(row-(\\d+)|fault-(\\d+))\\.png\"").matcher(html);
        while (img.find()) {
            drawn.add(img.group(2) != null ? Integer.parseInt(img.group(2)) : kinds.get(img.group(3)).get(0));
        }
        assertEquals(24, drawn.size(), "24 pictures: " + drawn);
        for (List<Integer> kind : kinds.values()) {
            int taken = (int) kind.stream().filter(drawn::contains).count();
            assertEquals(kind.subList(0, taken), kind.stream().filter(drawn::contains).toList(), "a kind's first ones: " + kind);
        }
        assertTrue(html.contains("Pictures: 24 of the " + all + " failures and findings of this folder are drawn"), html);
        assertTrue(html.contains("replay . --row <var>N</var> --png <var>FILE</var>"), "how to draw the rest");
    }
}
