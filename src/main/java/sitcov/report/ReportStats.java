package sitcov.report;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import sitcov.analysis.Finding;
import sitcov.experiment.Measure;
import sitcov.faults.Fault;
import sitcov.report.HtmlTable.Column;
import sitcov.results.CsvTable;
import sitcov.results.ResultsFolder;
import sitcov.verdict.VerdictText;

/**
 * stats.csv in the report: for each pair of drivers a table of the measures and one of the faults,
 * each with the columns a reader needs (the rest are in the file), numbers written for people.
 */
final class ReportStats {
    /** The measures' columns for drivers a and b: their names head their columns, at any width. */
    private static List<Column> measureColumns(String a, String b) {
        return List.of(Column.text("measure"), Column.text("finding"), Column.number(a), Column.number(b),
                Column.number("difference (95 % CI)"), Column.number("p (Holm)"), Column.number("equivalence p (margin)"),
                Column.number("could detect"), Column.text("higher in (paired)"));
    }

    private static List<Column> faultColumns(String a, String b) {
        return List.of(Column.text("fault"), Column.text("finding"), Column.number(a), Column.number(b),
                Column.number("difference, points (95 % CI)"), Column.number("q (BH)"),
                Column.text("pooled: found / maps of each"), Column.number("odds ratio (95 % CI)"));
    }

    private ReportStats() {
    }

    static void append(StringBuilder h, CsvTable stats) {
        h.append("<h2>Statistics of every pair of drivers</h2><p class=\"muted\">from <a href=\"").append(ResultsFolder.STATS)
                .append("\">").append(ResultsFolder.STATS).append("</a> (all its columns there). The difference is the"
                + " mean over paired replications of the first driver's value minus the second's; p is adjusted over the"
                + " measures' family by closed testing (the primary test's own p for the primary); \"could detect\" is the"
                + " difference the test would have found with 80 % probability; \"higher in\" counts the paired replications"
                + " in which each driver was ahead. For a fault, a screening, each replication's share of its maps finding it"
                + " is compared and q is Benjamini-Hochberg's; the pooled counts and odds ratio only describe.</p>");
        Map<String, List<List<String>>> pairs = new LinkedHashMap<>();
        for (List<String> r : stats.rows()) {
            pairs.computeIfAbsent(stats.get(r, "driver_a") + " against " + stats.get(r, "driver_b"), k -> new ArrayList<>())
                    .add(r);
        }
        pairs.forEach((pair, rows) -> {
            String a = stats.get(rows.get(0), "driver_a");
            String b = stats.get(rows.get(0), "driver_b");
            h.append("<h3>").append(HtmlReport.esc(pair)).append("</h3>");
            HtmlTable measures = new HtmlTable("Measures: mean over replications; difference " + a + " − " + b,
                    measureColumns(a, b));
            HtmlTable found = new HtmlTable("Faults: each driver's maps finding the fault (mean over replications)",
                    faultColumns(a, b));
            for (List<String> r : rows) {
                if (stats.get(r, "kind").equals("measure")) {
                    measures.row(measureRow(stats, r, a, b));
                } else {
                    found.row(faultRow(stats, r, a, b));
                }
            }
            measures.appendTo(h);
            found.appendTo(h);
        });
    }

    private static List<String> measureRow(CsvTable s, List<String> r, String a, String b) {
        String margin = s.get(r, "margin");
        String tost = s.get(r, "p_tost_adjusted").isEmpty() ? s.get(r, "p_tost") : s.get(r, "p_tost_adjusted");
        String ahead = s.get(r, "higher_a").isEmpty() ? HtmlNumbers.NONE : s.get(r, "higher_a") + " : "
                + s.get(r, "higher_b") + " of " + s.get(r, "replications");
        String detectable = s.get(r, "detectable_80");
        return List.of(Measure.ofKey(s.get(r, "name")).words(), finding(s, r, a, b), HtmlNumbers.mean(s.get(r, "mean_a")),
                HtmlNumbers.mean(s.get(r, "mean_b")), difference(s, r, false),
                HtmlNumbers.p(s.get(r, "p_adjusted")),
                tost.isEmpty() ? HtmlNumbers.NONE : HtmlNumbers.p(tost) + " (±" + VerdictText.plain(Double.parseDouble(margin))
                        + ")",
                detectable.equals("Infinity") ? "none at this n" : HtmlNumbers.mean(detectable),
                ahead);
    }

    private static List<String> faultRow(CsvTable s, List<String> r, String a, String b) {
        int id = Integer.parseInt(s.get(r, "name").replace("fault_", ""));
        String label = Fault.ofId(id).label();
        String ratio = s.get(r, "odds_ratio_pooled");
        return List.of(id + " " + label, finding(s, r, a, b), HtmlNumbers.percent(s.get(r, "mean_a")),
                HtmlNumbers.percent(s.get(r, "mean_b")), difference(s, r, true), HtmlNumbers.p(s.get(r, "p_adjusted")),
                s.get(r, "found_a") + "/" + s.get(r, "maps_a") + "; " + s.get(r, "found_b") + "/" + s.get(r, "maps_b"),
                ratio.isEmpty() ? HtmlNumbers.NONE : HtmlNumbers.mean(ratio) + " (" + HtmlNumbers.mean(s.get(r, "or_low"))
                        + "–" + HtmlNumbers.mean(s.get(r, "or_high")) + ")");
    }

    /** "higher for random", "equivalent", "not testable: found by neither driver", and "(primary)". */
    private static String finding(CsvTable s, List<String> r, String a, String b) {
        String key = s.get(r, "finding");
        Finding f = java.util.Arrays.stream(Finding.values()).filter(x -> x.key().equals(key)).findFirst().orElseThrow();
        String words = switch (f) {
            case HIGHER_A -> "higher for " + a;
            case HIGHER_B -> "higher for " + b;
            case EQUIVALENT -> "equivalent";
            case INCONCLUSIVE -> "inconclusive";
            case TOO_FEW -> "not tested";
            case NOT_TESTABLE -> "not testable";
        };
        String note = s.get(r, "note");
        return (s.get(r, "role").equals("primary") ? "primary: " : "") + words + (note.isEmpty() ? "" : ": " + note);
    }

    private static String difference(CsvTable s, List<String> r, boolean points) {
        if (s.get(r, "finding").equals(Finding.NOT_TESTABLE.key())) {
            return HtmlNumbers.NONE;
        }
        if (points) {
            return HtmlNumbers.points(s.get(r, "difference")) + " (" + HtmlNumbers.points(s.get(r, "ci_low")) + " to "
                    + HtmlNumbers.points(s.get(r, "ci_high")) + ")";
        }
        return HtmlNumbers.signed(s.get(r, "difference")) + " (" + HtmlNumbers.mean(s.get(r, "ci_low")) + " to "
                + HtmlNumbers.mean(s.get(r, "ci_high")) + ")";
    }
}
