package sitcov.report;

import java.util.List;
import java.util.OptionalDouble;
import sitcov.analysis.CampaignAnalysis;
import sitcov.analysis.PairedTrials;
import sitcov.experiment.CampaignConfig;
import sitcov.figures.CampaignFigure;
import sitcov.verdict.VerdictText;

/**
 * {@code campaign.html} of a campaign of the reference's own requirements: the verdict, per requirement and driver
 * the trials falsified and how soon with their intervals, the paired tests per pair, the figure.
 */
final class RequirementPage {
    private RequirementPage() {
    }

    static String html(CampaignAnalysis a, List<String> verdict) {
        CampaignConfig c = a.config();
        StringBuilder h = HtmlReport.pageStart(c.name());
        h.append("<h1>").append(HtmlReport.esc(c.name())).append("</h1><p class=\"muted\">campaign of the requirements of ")
                .append(HtmlReport.esc(c.controller())).append(" · master seed ").append(c.masterSeed()).append(" · ")
                .append(c.trials()).append(" trials per driver and requirement · at most ").append(c.tickBudget())
                .append(" ticks a trial · drivers ").append(HtmlReport.esc(String.join(", ", c.drivers()))).append("</p>\n");
        h.append("<h2>Verdict</h2><div class=\"verdict\">");
        verdict.forEach(line -> h.append("<p>").append(HtmlReport.esc(line)).append("</p>"));
        h.append("</div>\n<h2>Per requirement and driver</h2>\n");
        HtmlTable drivers = new HtmlTable("trials falsified with the 95 % Wilson interval; Kaplan–Meier median ticks to the"
                + " first failure with the 95 % Brookmeyer–Crowley interval; over the falsified trials, mean ticks and"
                + " median / mean maps", List.of(HtmlTable.Column.text("requirement"), HtmlTable.Column.text("driver"),
                HtmlTable.Column.number("falsified", "falsified"), HtmlTable.Column.number("95 % CI"),
                HtmlTable.Column.number("median ticks", "km_median_ticks"), HtmlTable.Column.number("95 % CI"),
                HtmlTable.Column.number("mean ticks", "mean_ticks_to_failure"), HtmlTable.Column.number("maps, median / mean"),
                HtmlTable.Column.number("distinct failures", "distinct_failures")));
        for (CampaignAnalysis.DriverResult r : a.drivers()) {
            drivers.row(List.of(r.target().key(), r.driver(), r.falsified() + " of " + r.trials(),
                    share(r.share().low()) + " – " + share(r.share().high()), ticks(r.medianTicks()),
                    ticks(r.medianInterval().low()) + " – " + ticks(r.medianInterval().high()),
                    r.meanTicks().isPresent() ? ticks(r.meanTicks()) : "",
                    r.medianMaps().isPresent() ? VerdictText.plain(r.medianMaps().getAsDouble()) + " / "
                            + VerdictText.number(r.meanMaps().getAsDouble()) : "",
                    Integer.toString(r.distinctFailures())));
        }
        drivers.appendTo(h);
        h.append("<h2>Pairs of drivers, paired by trial</h2>\n");
        HtmlTable pairs = new HtmlTable("McNemar's exact test on falsified (only A / only B: trials only one driver"
                + " falsified) and the log-rank test stratified by trial (first: trials in which each falsified first),"
                + " Holm-adjusted together; a test that cannot reach 0.05 is not made", List.of(
                HtmlTable.Column.text("requirement"), HtmlTable.Column.text("pair"),
                HtmlTable.Column.number("only A / only B"), HtmlTable.Column.number("McNemar Holm p", "mcnemar_p_holm"),
                HtmlTable.Column.number("first A / first B"), HtmlTable.Column.number("log-rank Holm p", "logrank_p_holm"),
                HtmlTable.Column.text("not tested")));
        for (PairedTrials t : a.paired()) {
            pairs.row(List.of(t.target().key(), t.a() + " vs " + t.b(), t.onlyA() + " / " + t.onlyB(),
                    VerdictText.p(t.mcNemarHolm()), t.logRank().firstA() + " / " + t.logRank().firstB(),
                    VerdictText.p(t.logRankHolm()), t.why()));
        }
        pairs.appendTo(h);
        h.append("<h2>Figure</h2>\n<p><a href=\"").append(CampaignFigure.FILE).append("\"><img src=\"")
                .append(CampaignFigure.FILE).append("\" alt=\"trials not yet falsified against ticks\"></a></p>\n");
        h.append("<p class=\"muted\">campaign.csv has one row per requirement, driver and trial, with the map that"
                + " falsified it; each requirement's trials are an ordinary results folder (requirement-KEY/runs.csv, one"
                + " row per simulated run).</p></body></html>\n");
        return h.toString();
    }

    private static String share(double v) {
        return String.format(java.util.Locale.ROOT, "%.2f", v);
    }

    private static String ticks(OptionalDouble v) {
        return v.isPresent() ? Long.toString(Math.round(v.getAsDouble())) : "not reached";
    }
}
