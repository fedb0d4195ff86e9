package sitcov.report;

import java.util.ArrayList;
import java.util.List;
import sitcov.report.HtmlTable.Column;
import sitcov.results.CsvTable;
import sitcov.results.ResultsFolder;
import sitcov.verdict.VerdictText;

/**
 * Table 2 (each driver's share of maps finding each fault, and the differences between drivers) and
 * the uniformity test's table, as the report shows them: shares in per cent, differences in points.
 */
final class ReportFaultTables {
    private static final String MINUS = "_minus_";

    private ReportFaultTables() {
    }

    static void table2(StringBuilder h, CsvTable t, List<String> drivers) {
        h.append("<h2>Table 2: the share of maps finding each fault</h2><p class=\"muted\">from <a href=\"")
                .append(ResultsFolder.TABLE2).append("\">").append(ResultsFolder.TABLE2).append("</a>: the mean over"
                + " replications of each replication's share of its maps finding the fault; differences in percentage"
                + " points</p>");
        if (t.isEmpty()) {
            return;
        }
        List<String> differences = t.header().stream().filter(c -> c.contains(MINUS)).toList();
        boolean inline = differences.size() == 1;
        List<Column> columns = new ArrayList<>(List.of(Column.text("fault"), Column.text("notion")));
        drivers.forEach(d -> columns.add(Column.number(d)));
        if (inline) {
            columns.add(Column.number(differences.get(0).replace(MINUS, " − ")));
        }
        HtmlTable shares = new HtmlTable("", columns);
        List<Column> diffColumns = new ArrayList<>(List.of(Column.text("fault"), Column.text("notion")));
        differences.forEach(c -> diffColumns.add(Column.number(c.replace(MINUS, " − "))));
        HtmlTable diffs = new HtmlTable("Differences between drivers, percentage points", diffColumns);
        for (List<String> r : t.rows()) {
            String fault = t.get(r, "fault") + " " + t.get(r, "name");
            List<String> cells = new ArrayList<>(List.of(fault, t.get(r, "notion")));
            drivers.forEach(d -> cells.add(HtmlNumbers.percent(t.get(r, d))));
            if (inline) {
                cells.add(HtmlNumbers.points(t.get(r, differences.get(0))));
            }
            shares.row(cells);
            List<String> d = new ArrayList<>(List.of(fault, t.get(r, "notion")));
            differences.forEach(c -> d.add(HtmlNumbers.points(t.get(r, c))));
            diffs.row(d);
        }
        shares.appendTo(h);
        if (!inline && !differences.isEmpty()) {
            diffs.appendTo(h);
        }
    }

    static void uniformity(StringBuilder h, CsvTable u) {
        h.append("<h2>Situations against faults: the uniformity test</h2><p class=\"muted\">from <a href=\"")
                .append(ResultsFolder.UNIFORMITY).append("\">").append(ResultsFolder.UNIFORMITY).append("</a>: over"
                + " distinct maps (a map run by several drivers counted once), the share of the variation in whether a"
                + " map finds the fault that its coverage cell explains, against the same share when the maps are dealt"
                + " to cells at random; faults found or missed on fewer than ").append(VerdictText.UNIFORMITY_MIN_MAPS)
                .append(" maps are too rare to test and left out of the verdict's average</p>");
        if (u.isEmpty()) {
            return;
        }
        HtmlTable table = new HtmlTable("", List.of(Column.text("fault"), Column.number("distinct maps"),
                Column.number("found on"), Column.number("explained by cell"), Column.number("by chance"),
                Column.number("p (permutation)"), Column.text("in the verdict")));
        for (List<String> r : u.rows()) {
            int id = Integer.parseInt(u.get(r, "fault"));
            int maps = Integer.parseInt(u.get(r, "maps"));
            int found = Integer.parseInt(u.get(r, "found"));
            String label = sitcov.faults.Fault.ofId(id).label();
            String counted = VerdictText.leftOut(found, maps).map(why -> "no: " + why).orElse("yes");
            table.row(List.of(id + " " + label, HtmlNumbers.number(u.get(r, "maps")), HtmlNumbers.number(u.get(r, "found")),
                    HtmlNumbers.percent(u.get(r, "explained_by_cell")), HtmlNumbers.percent(u.get(r, "explained_by_chance")),
                    HtmlNumbers.p(u.get(r, "p_permutation")), counted));
        }
        table.appendTo(h);
    }
}
