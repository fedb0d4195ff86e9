package sitcov.report;

import java.util.List;
import sitcov.report.HtmlTable.Column;
import sitcov.results.CsvTable;
import sitcov.results.ResultsFolder;

/** own-failures.csv in the report: the first maps on which the fault-free car failed, each with its replay command. */
final class ReportOwnFailures {
    /** Rows shown; the file has them all. */
    static final int SHOWN = 40;

    private ReportOwnFailures() {
    }

    /** {@code builtinCar}: the reference is the builtin car and its variants are its seeded faults. */
    static void append(StringBuilder h, CsvTable own, boolean builtinCar) {
        h.append(builtinCar ? "<h2>The reference car's own failures</h2><p class=\"muted\">maps on which the fault-free car"
                + " had an accident by itself (" : "<h2>The reference controller's own failures</h2><p class=\"muted\">maps"
                + " on which the reference run had an accident or its controller failed (").append(own.rows().size()).append(" in all, in <a href=\"")
                .append(ResultsFolder.OWN_FAILURES).append("\">").append(ResultsFolder.OWN_FAILURES)
                .append("</a>); each command replays the map from this folder.</p>\n");
        if (own.isEmpty()) {
            return;
        }
        HtmlTable table = new HtmlTable(own.rows().size() > SHOWN ? "the first " + SHOWN : "",
                List.of(Column.number("replication"), Column.text("driver"), Column.text("map"), Column.number("cell"),
                        Column.text("accidents"), Column.text("replay")));
        for (List<String> r : own.rows().subList(0, Math.min(SHOWN, own.rows().size()))) {
            table.row(List.of(own.get(r, "replication"), own.get(r, "driver"), own.get(r, "map"), own.get(r, "cell"),
                    own.get(r, "accidents"), own.get(r, "replay")));
        }
        table.appendTo(h);
    }
}
