package sitcov.report;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import sitcov.experiment.Measure;
import sitcov.report.HtmlTable.Column;
import sitcov.results.CsvTable;
import sitcov.results.ResultsFolder;
import sitcov.stats.Descriptive;
import sitcov.verdict.VerdictText;

/**
 * The paper's measures in the report: per driver and notion their mean over replications with the
 * range, then every replication's row folded below (summary.csv holds them all, faults included).
 */
final class ReportMeasures {
    /**
     * summary.csv's columns shown, with the words a reader knows them by: a measure's column is named by its
     * key and headed by its label; the share of faults found is no {@link Measure} (no test compares it).
     */
    private static final List<Column> MEASURES = List.of(column(Measure.MAPS_RUN), column(Measure.CELLS_COVERED),
            Column.number("share of faults found", "method_prop_fault"), column(Measure.PROP_MAP_ALL_FAULT),
            column(Measure.AVG_MAP_FAULT));

    private ReportMeasures() {
    }

    private static Column column(Measure m) {
        return Column.number(m.label(), m.key());
    }

    static void append(StringBuilder h, CsvTable summary) {
        h.append("<h2>The paper's measures</h2><p class=\"muted\">from <a href=\"").append(ResultsFolder.SUMMARY)
                .append("\">").append(ResultsFolder.SUMMARY).append("</a>: mean over replications, the range in"
                + " brackets; \"differential\" counts a fault found when the faulty run has an accident the fault-free run"
                + " has not, \"paper\" when it has any accident</p>");
        if (summary.isEmpty()) {
            return;
        }
        Map<String, List<List<String>>> groups = new LinkedHashMap<>();
        for (List<String> r : summary.rows()) {
            groups.computeIfAbsent(summary.get(r, "driver") + "," + summary.get(r, "notion"), k -> new ArrayList<>()).add(r);
        }
        List<Column> columns = new ArrayList<>(List.of(Column.text("driver"), Column.text("notion"),
                Column.number("replications")));
        columns.addAll(MEASURES);
        HtmlTable means = new HtmlTable("", columns);
        groups.forEach((key, rows) -> {
            List<String> cells = new ArrayList<>(List.of(key.split(",")));
            cells.add(String.valueOf(rows.size()));
            for (Column c : MEASURES) {
                cells.add(meanAndRange(summary, rows, c.key()));
            }
            means.row(cells);
        });
        means.appendTo(h);
        List<Column> every = new ArrayList<>(List.of(Column.text("driver"), Column.number("replication"),
                Column.text("notion")));
        every.addAll(MEASURES);
        HtmlTable replications = new HtmlTable("", every);
        for (List<String> r : summary.rows()) {
            List<String> cells = new ArrayList<>(List.of(summary.get(r, "driver"), summary.get(r, "replication"),
                    summary.get(r, "notion")));
            for (Column c : MEASURES) {
                cells.add(format(c.key(), summary.get(r, c.key())));
            }
            replications.row(cells);
        }
        h.append("<details><summary>Every replication (").append(replications.rows()).append(" rows; each fault's share"
                + " is in summary.csv)</summary>");
        replications.appendTo(h);
        h.append("</details>\n");
    }

    private static String meanAndRange(CsvTable summary, List<List<String>> rows, String column) {
        double[] v = rows.stream().mapToDouble(r -> Double.parseDouble(summary.get(r, column))).toArray();
        double min = java.util.Arrays.stream(v).min().orElse(Double.NaN);
        double max = java.util.Arrays.stream(v).max().orElse(Double.NaN);
        String mean = percent(column) ? HtmlNumbers.percent(Descriptive.mean(v)) : VerdictText.number(Descriptive.mean(v));
        return min == max ? mean : mean + " (" + bound(column, min) + "–" + bound(column, max) + ")";
    }

    /** Shares in per cent, counts and means as numbers. */
    private static String format(String column, String value) {
        return percent(column) ? HtmlNumbers.percent(value) : HtmlNumbers.number(value);
    }

    /** A bound of a range: a share in per cent without the sign, which the mean before it carries. */
    private static String bound(String column, double v) {
        return percent(column) ? HtmlNumbers.percent(v).replace(" %", "") : HtmlNumbers.number(v);
    }

    private static boolean percent(String column) {
        return column.startsWith("method_prop") || column.startsWith("prop_");
    }
}
