package sitcov.report;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import sitcov.experiment.ExperimentConfig;
import sitcov.experiment.MapRun;
import sitcov.results.CsvTable;
import sitcov.results.Manifest;
import sitcov.results.ResultsFolder;
import sitcov.verdict.PairSummary;

/**
 * {@code report.html}: one self-contained page per results folder (its own CSS, no script, nothing
 * fetched): the verdict, the paper's measures, the statistics, Table 2, every figure of the folder,
 * the coverage grid as slices with the maps run per cell, and for each fault the maps that found it
 * with the command that replays each. Tables are read back from the folder's CSV files, so the page
 * shows exactly what the files hold.
 */
final class HtmlReport {
    static final String CSS = """
            body{font-family:system-ui,-apple-system,'Segoe UI',sans-serif;max-width:1100px;margin:0 auto;padding:1em;\
            color:#1e1e1e;line-height:1.45}
            h1{font-size:1.6em;margin-bottom:.2em}h2{margin-top:1.6em;border-bottom:1px solid #ccc}h3{margin:1.2em 0 .3em}
            table{border-collapse:collapse;font-size:.85em;margin:.5em 0}caption{text-align:left;font-weight:600;padding:.2em 0}
            th,td{border:1px solid #ccc;padding:.2em .45em;text-align:left;vertical-align:top}
            th{background:#f3f1ec;font-weight:600}th.n{white-space:normal}table.stack td:nth-child(-n+2){min-width:8em}.n{text-align:right;white-space:nowrap;font-variant-numeric:tabular-nums}
            .key{display:block;font-weight:400;font-size:.8em;color:#777}
            img{max-width:100%;height:auto;border:1px solid #ddd;margin:.4em 0}
            code{background:#f3f1ec;padding:0 .25em;font-size:.85em}code.cmd span{white-space:nowrap}
            .verdict li{margin:.3em 0}.slices{display:flex;flex-wrap:wrap;gap:.8em}
            table.grid{font-size:.75em}table.grid td{min-width:2em;text-align:center}table.grid th{font-weight:400}
            .muted{color:#666}details{margin:.5em 0}summary{cursor:pointer;color:#245}
            .shots{display:grid;grid-template-columns:repeat(auto-fill,minmax(480px,1fr));gap:.6em}\
            .shots figure{margin:0}.shots figcaption{font-size:.85em;color:#555}
            @media (max-width:640px){table.stack,table.stack tbody,table.stack tr,table.stack td{display:block}\
            table.stack thead{display:none}table.stack caption{display:block}table.stack tr{border:1px solid #ccc;margin:.5em 0}\
            table.stack td{border:none;border-bottom:1px solid #eee;text-align:left;white-space:normal}\
            table.stack td::before{content:attr(data-label) ": ";font-weight:600;color:#555}}
            @media print{body{max-width:none;padding:0;font-size:10pt}h2,h3{break-after:avoid}\
            img,tr,li{break-inside:avoid}table{font-size:8pt}a{color:inherit}\
            *{-webkit-print-color-adjust:exact;print-color-adjust:exact}}
            @page{margin:1.2cm}
            """;

    private HtmlReport() {
    }

    /** A page of a results folder up to its body: its title, and the style every page shares. */
    static StringBuilder pageStart(String title) {
        return new StringBuilder().append("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">")
                .append("<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">")
                .append("<title>sitcov: ").append(esc(title)).append("</title><style>").append(CSS)
                .append("</style></head><body>\n");
    }

    static String html(Path folder, ExperimentConfig config, List<MapRun> inOrder, ReportPictures pictures)
            throws IOException {
        StringBuilder h = pageStart(config.name());
        h.append("<h1>").append(esc(config.name())).append("</h1><p class=\"muted\">master seed ")
                .append(config.masterSeed()).append(" · ").append(config.replications()).append(" replications · drivers ")
                .append(esc(String.join(", ", config.drivers()))).append(" · ").append(config.candidates())
                .append(" candidates · budget ").append(esc(config.budget().key()))
                .append(config.onlySeeded() && !config.variants().isEmpty()
                        ? " · faults " + esc(sitcov.faults.FaultSet.format(config.faults()))
                        : " · controller " + esc(config.controller()) + " · variants " + esc(variants(config)))
                .append(" · faulty runs ")
                .append(esc(config.faultyRuns().key())).append("</p>\n");
        h.append("<h2>Verdict</h2><div class=\"verdict\">");
        verdict(h, lines(folder, ResultsFolder.VERDICT));
        h.append("</div>\n");
        ReportMeasures.append(h, CsvTable.read(folder.resolve(ResultsFolder.SUMMARY)));
        ReportStats.append(h, CsvTable.read(folder.resolve(ResultsFolder.STATS)));
        ReportFaultTables.table2(h, CsvTable.read(folder.resolve(ResultsFolder.TABLE2)), config.drivers());
        if (java.nio.file.Files.exists(folder.resolve(ResultsFolder.OWN_FAILURES))) {
            ReportOwnFailures.append(h, CsvTable.read(folder.resolve(ResultsFolder.OWN_FAILURES)),
                    config.onBuiltinFaults());
            ReportPictures.append(h, folder, pictures.of(java.util.Optional.empty()), "Replayed from their recorded"
                    + " commands (which are pictured: under <a href=\"#found\">Maps that found each fault</a>):",
                    p -> ReportPictures.where(p) + ": " + String.join("+",
                            sitcov.analysis.OwnFailures.types(p.run()).stream().map(Enum::name).toList()));
        }
        h.append("<h2>Figures</h2><p class=\"muted\">each opens at full size</p>\n");
        for (String fig : figures(folder)) {
            h.append("<p><a href=\"").append(esc(fig)).append("\"><img src=\"").append(esc(fig)).append("\" alt=\"")
                    .append(esc(fig)).append("\"></a></p>\n");
        }
        ReportGrid.append(h, config.grid(), config.drivers(), inOrder);
        ReportFaultMaps.append(h, folder, config, inOrder, version(folder), pictures);
        ReportFaultTables.uniformity(h, CsvTable.read(folder.resolve(ResultsFolder.UNIFORMITY)));
        h.append("<p class=\"muted\">Every table above is a CSV file in this folder; runs.csv has one row per"
                + " simulated run.</p></body></html>\n");
        return h.toString();
    }

    /**
     * The verdict's lines: headings ("## ...") as headings, "In short: ..." in bold, items ("- ...") as
     * a list under the line before them, the rest as paragraphs.
     */
    /** Each variant as id label (spec), or none. */
    private static String variants(ExperimentConfig config) {
        if (config.variants().isEmpty()) {
            return "none (the reference's own failures)";
        }
        return String.join("; ", config.variants().stream().map(v -> v.id() + " " + v.label() + " (" + v.spec() + ")").toList());
    }

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
            if (item) {
                h.append("<li>").append(esc(line.substring(2))).append("</li>");
            } else if (line.startsWith(PairSummary.HEADING)) {
                h.append("<h3>").append(esc(line.substring(PairSummary.HEADING.length()))).append("</h3>");
            } else if (line.startsWith(PairSummary.IN_SHORT)) {
                h.append("<p><strong>").append(esc(line)).append("</strong></p>");
            } else {
                h.append("<p>").append(esc(line)).append("</p>");
            }
        }
        h.append(inList ? "</ul>" : "");
    }

    /** A shell command as code that wraps only between its words, never inside one. */
    static String command(String command) {
        StringBuilder c = new StringBuilder("<code class=\"cmd\">");
        String[] words = command.split(" ");
        for (int i = 0; i < words.length; i++) {
            c.append(i == 0 ? "" : " ").append("<span>").append(esc(words[i])).append("</span>");
        }
        return c.append("</code>").toString();
    }

    /** The version of sitcov that wrote the folder, for the jar's name in replay commands. */
    private static String version(Path folder) {
        try {
            return Manifest.read(folder).version();
        } catch (IOException | RuntimeException e) {
            return "VERSION";
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
