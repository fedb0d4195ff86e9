package sitcov.report;

import java.util.ArrayList;
import java.util.List;

/**
 * One table of the HTML report, built so it reads at any width and in print: few columns, text
 * left and numbers right, and each cell labelled with its column so that a narrow screen can stack
 * a row's cells under one another (the page's CSS does that below 640 px) instead of cutting them off.
 */
final class HtmlTable {
    /** A column: its heading, whether it holds numbers (right-aligned), and the CSV column it shows, if any. */
    record Column(String heading, boolean number, String key) {
        static Column text(String heading) {
            return new Column(heading, false, "");
        }

        static Column number(String heading) {
            return new Column(heading, true, "");
        }

        static Column number(String heading, String key) {
            return new Column(heading, true, key);
        }
    }

    private final String caption;
    private final List<Column> columns;
    private final List<List<String>> rows = new ArrayList<>();

    HtmlTable(String caption, List<Column> columns) {
        this.caption = caption;
        this.columns = List.copyOf(columns);
    }

    /** Adds a row of plain text cells, one per column (escaped when drawn). */
    HtmlTable row(List<String> cells) {
        if (cells.size() != columns.size()) {
            throw new IllegalArgumentException(cells.size() + " cells for " + columns.size() + " columns");
        }
        rows.add(List.copyOf(cells));
        return this;
    }

    int rows() {
        return rows.size();
    }

    void appendTo(StringBuilder h) {
        h.append("<table class=\"stack\">");
        if (!caption.isEmpty()) {
            h.append("<caption>").append(HtmlReport.esc(caption)).append("</caption>");
        }
        h.append("<thead><tr>");
        for (Column c : columns) {
            h.append(c.number() ? "<th class=\"n\">" : "<th>").append(HtmlReport.esc(c.heading()));
            if (!c.key().isEmpty()) {
                h.append(" <span class=\"key\">").append(HtmlReport.esc(c.key())).append("</span>");
            }
            h.append("</th>");
        }
        h.append("</tr></thead><tbody>");
        for (List<String> r : rows) {
            h.append("<tr>");
            for (int i = 0; i < r.size(); i++) {
                Column c = columns.get(i);
                h.append(c.number() ? "<td class=\"n\"" : "<td").append(" data-label=\"").append(HtmlReport.esc(c.heading()))
                        .append("\">").append(HtmlReport.esc(r.get(i))).append("</td>");
            }
            h.append("</tr>");
        }
        h.append("</tbody></table>\n");
    }
}
