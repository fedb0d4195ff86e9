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
import sitcov.report.ResultsFolder;

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
    void theReportShowsTheVerdictAndOneRowPerRunOfEachTable() throws Exception {
        Path folder = ResultsFolders.tinyReference();
        String html = Files.readString(folder.resolve(ResultsFolder.REPORT));
        for (String line : Files.readAllLines(folder.resolve(ResultsFolder.VERDICT))) {
            boolean item = line.startsWith("- ");
            String shown = line.replaceFirst("^- ", "").replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")
                    .replace("\"", "&quot;");
            assertTrue(html.contains(item ? "<li>" + shown + "</li>" : "<p>" + shown + "</p>"), "verdict line missing: " + line);
        }
        long summaryRows = Files.readAllLines(folder.resolve(ResultsFolder.SUMMARY)).size();
        int start = html.indexOf("The paper's measures per replication");
        int end = html.indexOf("</table>", start);
        assertEquals(summaryRows, html.substring(start, end).split("<tr>", -1).length - 1, "a table row per CSV row");
        assertEquals(html.indexOf("<script"), -1, "no script");
    }
}
