package sitcov.report;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;
import sitcov.experiment.ExperimentConfig;
import sitcov.experiment.MapRun;

/**
 * {@code report.html}: one self-contained page per results folder (its own CSS, no script, nothing
 * fetched): the verdict, the paper's measures, the statistics, Table 2, every figure of the folder,
 * the coverage grid as slices with the maps run per cell, and for each fault the maps that found it
 * with the command that replays each. Tables are read back from the folder's CSV files, so the page
 * shows exactly what the files hold.
 */
final class HtmlReport {
    /** Maps listed per fault; the rest are in runs.csv. */
    static final int MAPS_PER_FAULT = 10;
    private static final String CSS = """
            body{font-family:system-ui,-apple-system,'Segoe UI',sans-serif;max-width:1100px;margin:0 auto;padding:1em;\
            color:#1e1e1e;line-height:1.45}
            h1{font-size:1.6em;margin-bottom:.2em}h2{margin-top:1.6em;border-bottom:1px solid #ccc}
            .scroll{overflow-x:auto}table{border-collapse:collapse;font-size:.85em;margin:.5em 0}
            th,td{border:1px solid #ccc;padding:.2em .45em;text-align:right;white-space:nowrap}
            th{background:#f3f1ec}td:first-child,th:first-child{text-align:left}
            img{max-width:100%;height:auto;border:1px solid #ddd;margin:.4em 0}
            code{background:#f3f1ec;padding:0 .25em;font-size:.85em;word-break:break-all}
            .verdict li{margin:.3em 0}.slices{display:flex;flex-wrap:wrap;gap:1em}
            .slices td{width:2.2em;height:1.5em;text-align:center}.muted{color:#666}
            @media print{body{max-width:none}h2{page-break-after:avoid}img,table{page-break-inside:avoid}}
            """;

    private HtmlReport() {
    }

    static String html(Path folder, ExperimentConfig config, List<MapRun> inOrder) throws IOException {
        StringBuilder h = new StringBuilder();
        h.append("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">")
                .append("<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">")
                .append("<title>sitcov: ").append(esc(config.name())).append("</title><style>").append(CSS)
                .append("</style></head><body>\n");
        h.append("<h1>").append(esc(config.name())).append("</h1><p class=\"muted\">master seed ")
                .append(config.masterSeed()).append(" · ").append(config.replications()).append(" replications · drivers ")
                .append(esc(String.join(", ", config.drivers()))).append(" · ").append(config.candidates())
                .append(" candidates · budget ").append(esc(config.budget().key())).append(" · faults ")
                .append(esc(sitcov.faults.FaultSet.format(config.faults()))).append(" · faulty runs ")
                .append(esc(config.faultyRuns().key())).append("</p>\n");
        h.append("<h2>Verdict</h2><div class=\"verdict\">");
        verdict(h, lines(folder, ResultsFolder.VERDICT));
        h.append("</div>\n");
        section(h, "The paper's measures per replication", folder, ResultsFolder.SUMMARY);
        stats(h, lines(folder, ResultsFolder.STATS));
        section(h, "Table 2: the share of maps finding each fault", folder, ResultsFolder.TABLE2);
        h.append("<h2>Figures</h2>\n");
        for (String fig : figures(folder)) {
            h.append("<p><img src=\"").append(esc(fig)).append("\" alt=\"").append(esc(fig)).append("\"></p>\n");
        }
        grid(h, folder, config);
        faults(h, folder, config, inOrder);
        section(h, "Situations against faults: the uniformity test", folder, ResultsFolder.UNIFORMITY);
        h.append("<p class=\"muted\">Every table above is a CSV file in this folder; runs.csv has one row per"
                + " simulated run.</p></body></html>\n");
        return h.toString();
    }

    private static void section(StringBuilder h, String title, Path folder, String csv) throws IOException {
        h.append("<h2>").append(esc(title)).append("</h2><p class=\"muted\">from <a href=\"").append(csv).append("\">")
                .append(csv).append("</a></p>");
        table(h, lines(folder, csv));
    }

    /** The verdict's lines: items ("- ...") as a list under the line before them, the rest as paragraphs. */
    private static void verdict(StringBuilder h, List<String> lines) {
        boolean inList = false;
        for (String line : lines) {
            boolean item = line.startsWith("- ");
            if (item && !inList) {
                h.append("<ul>");
            } else if (!item && inList) {
                h.append("</ul>");
            }
            inList = item;
            h.append(item ? "<li>" : "<p>").append(esc(item ? line.substring(2) : line)).append(item ? "</li>" : "</p>");
        }
        h.append(inList ? "</ul>" : "");
    }

    private static final List<String> MEASURE_COLUMNS = List.of("name", "driver_a", "driver_b", "role", "finding", "mean_a",
            "mean_b", "difference", "ci_low", "ci_high", "p_adjusted", "detectable_80", "margin", "p_tost_adjusted",
            "a12_unpaired", "note");
    private static final List<String> FAULT_COLUMNS = List.of("name", "driver_a", "driver_b", "finding", "mean_a", "mean_b",
            "difference", "ci_low", "ci_high", "p_adjusted", "dispersion_a", "dispersion_b", "found_a", "maps_a", "found_b",
            "maps_b", "p_fisher_pooled", "odds_ratio_pooled", "note");

    /** stats.csv as two tables, measures and faults, each with the columns that matter for it. */
    private static void stats(StringBuilder h, List<String> rows) {
        h.append("<h2>Statistics of every pair of drivers</h2><p class=\"muted\">from <a href=\"").append(ResultsFolder.STATS)
                .append("\">").append(ResultsFolder.STATS).append("</a> (all its columns there); difference = driver_a minus"
                + " driver_b over paired replications, for a fault of each replication's share of maps finding it;"
                + " p_adjusted is Holm-adjusted over the exploratory family (the primary test's own p for the primary);"
                + " the pooled Fisher p and odds ratio only describe</p>");
        if (rows.isEmpty()) {
            return;
        }
        List<String> header = List.of(rows.get(0).split(",", -1));
        for (String kind : List.of("measure", "fault")) {
            List<String> columns = kind.equals("measure") ? MEASURE_COLUMNS : FAULT_COLUMNS;
            List<String> kept = new ArrayList<>();
            kept.add(String.join(",", columns));
            for (String r : rows.subList(1, rows.size())) {
                List<String> v = List.of(r.split(",", -1));
                if (v.get(0).equals(kind)) {
                    kept.add(String.join(",", columns.stream().map(c -> v.get(header.indexOf(c))).toList()));
                }
            }
            table(h, kept);
        }
    }

    private static void table(StringBuilder h, List<String> rows) {
        h.append("<div class=\"scroll\"><table>");
        for (int i = 0; i < rows.size(); i++) {
            String cell = i == 0 ? "th" : "td";
            h.append("<tr>");
            for (String v : rows.get(i).split(",", -1)) {
                h.append('<').append(cell).append('>').append(esc(v)).append("</").append(cell).append('>');
            }
            h.append("</tr>");
        }
        h.append("</table></div>\n");
    }

    /** The grid's maps per cell as slices along its first criterion (a grid of three criteria). */
    private static void grid(StringBuilder h, Path folder, ExperimentConfig config) throws IOException {
        h.append("<h2>Coverage grid: distinct maps run per cell</h2>");
        var bins = config.grid().bins();
        if (bins.size() != 3) {
            h.append("<p>The grid has ").append(bins.size()).append(" criteria; its cells are listed in <a href=\"")
                    .append(ResultsFolder.CELL_FAULTS).append("\">").append(ResultsFolder.CELL_FAULTS).append("</a>.</p>");
            return;
        }
        Map<Integer, String> maps = new TreeMap<>();
        List<String> rows = lines(folder, ResultsFolder.CELL_FAULTS);
        for (String r : rows.subList(1, rows.size())) {
            String[] v = r.split(",");
            maps.put(Integer.parseInt(v[0]), v[1]);
        }
        var names = config.grid().criteria();
        int a = bins.get(0).count();
        int b = bins.get(1).count();
        int c = bins.get(2).count();
        h.append("<p class=\"muted\">one slice per bin of ").append(esc(names.get(0).key())).append("; rows: bins of ")
                .append(esc(names.get(1).key())).append(", columns: bins of ").append(esc(names.get(2).key()))
                .append("; empty: never run</p><div class=\"slices\">");
        for (int i = 0; i < a; i++) {
            h.append("<table><tr><th colspan=\"").append(c).append("\">").append(esc(names.get(0).key())).append(" bin ")
                    .append(i).append("</th></tr>");
            for (int j = 0; j < b; j++) {
                h.append("<tr>");
                for (int k = 0; k < c; k++) {
                    h.append("<td>").append(maps.getOrDefault(i * b * c + j * c + k, "")).append("</td>");
                }
                h.append("</tr>");
            }
            h.append("</table>");
        }
        h.append("</div>\n");
    }

    /** For each fault, the first maps that found it, each with its row of runs.csv and the command replaying it. */
    private static void faults(StringBuilder h, Path folder, ExperimentConfig config, List<MapRun> inOrder) {
        h.append("<h2>Maps that found each fault</h2><p class=\"muted\">DIR is this folder; the replay draws the"
                + " fault-free run and the faulty one side by side (add --gif FILE to watch them)</p>");
        var faults = config.faultList();
        int perMap = 1 + faults.size();
        for (int f = 0; f < faults.size(); f++) {
            List<String> found = new ArrayList<>();
            int total = 0;
            for (int m = 0; m < inOrder.size(); m++) {
                MapRun run = inOrder.get(m);
                var outcome = run.faults().get(f);
                if (outcome.found(false)) {
                    total++;
                    if (found.size() < MAPS_PER_FAULT) {
                        int row = m * perMap + f + 2;
                        found.add(String.format(Locale.ROOT, "<li>replication %d, %s, map %d (%s): %s at row %d — <code>"
                                + "sitcov replay DIR --row %d --png replay.png</code></li>", run.replication(), esc(run.driver()),
                                run.mapIndex(), esc(run.map().text()), outcome.newAccident().map(Enum::name).orElse("FOUND"),
                                row, row));
                    }
                }
            }
            h.append("<h3>fault ").append(faults.get(f).id()).append(" · ").append(esc(faults.get(f).label()))
                    .append("</h3><p>found on ").append(total).append(" of ").append(inOrder.size()).append(" maps")
                    .append(total > found.size() ? " (the first " + found.size() + " listed)" : "").append("</p>");
            if (!found.isEmpty()) {
                h.append("<ul>").append(String.join("", found)).append("</ul>");
            }
            Path picture = ReplayGallery.picture(folder, faults.get(f));
            if (Files.isRegularFile(picture)) {
                String name = ReplayGallery.FOLDER + "/" + picture.getFileName();
                h.append("<p>The first of them, replayed (left without the fault, right with it):<br><a href=\"").append(name)
                        .append("\"><img src=\"").append(name).append("\" alt=\"replay of the first map that found fault ")
                        .append(faults.get(f).id()).append("\"></a></p>");
            }
        }
    }

    private static List<String> figures(Path folder) throws IOException {
        try (var files = Files.list(folder)) {
            return files.map(p -> p.getFileName().toString()).filter(n -> n.startsWith("fig") && n.endsWith(".png"))
                    .sorted().toList();
        }
    }

    private static List<String> lines(Path folder, String name) throws IOException {
        Path file = folder.resolve(name);
        return Files.isRegularFile(file) ? Files.readAllLines(file) : List.of();
    }

    static String esc(String s) {
        return s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;").replace("\"", "&quot;");
    }
}
