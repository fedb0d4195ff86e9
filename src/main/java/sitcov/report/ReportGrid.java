package sitcov.report;

import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import sitcov.coverage.Bins;
import sitcov.coverage.GridDefinition;
import sitcov.experiment.MapRun;
import sitcov.results.ResultsFolder;

/**
 * The coverage grid in the report: for each driver, slices of a three-criteria grid along its first
 * criterion, rows and columns labelled with their bins in metres, each cell the distinct maps the
 * driver ran there over all replications, shaded by that count.
 */
final class ReportGrid {
    private ReportGrid() {
    }

    static void append(StringBuilder h, GridDefinition grid, List<String> drivers, List<MapRun> inOrder) {
        h.append("<h2>Coverage grid: each driver's maps per cell</h2>");
        var bins = grid.bins();
        if (bins.size() != 3) {
            h.append("<p>The grid has ").append(bins.size()).append(" criteria; its cells are listed in <a href=\"")
                    .append(ResultsFolder.CELL_FAULTS).append("\">").append(ResultsFolder.CELL_FAULTS).append("</a>.</p>");
            return;
        }
        var names = grid.criteria();
        h.append("<p class=\"muted\">distinct maps each driver ran in each cell, over all replications (darker: more);"
                + " one slice per bin of ").append(HtmlReport.esc(names.get(0).key())).append("; rows: ")
                .append(HtmlReport.esc(names.get(1).key())).append(", columns: ").append(HtmlReport.esc(names.get(2).key()))
                .append(", in metres; empty: never run</p>\n");
        for (String driver : drivers) {
            Map<Integer, Set<String>> maps = new LinkedHashMap<>();
            for (MapRun run : inOrder) {
                if (run.driver().equals(driver) && run.cell() >= 0) {
                    maps.computeIfAbsent(run.cell(), k -> new HashSet<>()).add(run.map().text());
                }
            }
            int most = maps.values().stream().mapToInt(Set::size).max().orElse(1);
            h.append("<h3>").append(HtmlReport.esc(driver)).append(": ").append(maps.size()).append(" of ")
                    .append(grid.cells()).append(" cells</h3><div class=\"slices\">");
            int b = bins.get(1).count();
            int c = bins.get(2).count();
            for (int i = 0; i < bins.get(0).count(); i++) {
                h.append("<table class=\"grid\"><caption>").append(HtmlReport.esc(names.get(0).key())).append(' ')
                        .append(HtmlReport.esc(range(bins.get(0), i))).append("</caption><tr><th></th>");
                for (int k = 0; k < c; k++) {
                    h.append("<th>").append(HtmlReport.esc(range(bins.get(2), k))).append("</th>");
                }
                h.append("</tr>");
                for (int j = 0; j < b; j++) {
                    h.append("<tr><th>").append(HtmlReport.esc(range(bins.get(1), j))).append("</th>");
                    for (int k = 0; k < c; k++) {
                        int n = maps.getOrDefault(grid.cellAt(i, j, k), Set.of()).size();
                        h.append(n == 0 ? "<td></td>" : String.format(Locale.ROOT,
                                "<td style=\"background:rgba(31,119,180,%.2f)\">%d</td>", 0.12 + 0.6 * n / most, n));
                    }
                    h.append("</tr>");
                }
                h.append("</table>");
            }
            h.append("</div>\n");
        }
    }

    /** A bin as people read it: "40–80", "≥ 26.01". */
    static String range(Bins bins, int bin) {
        double upper = bins.upper(bin);
        String lower = HtmlNumbers.number(bins.lower(bin));
        return Double.isInfinite(upper) ? "≥ " + lower : lower + "–" + HtmlNumbers.number(upper);
    }
}
