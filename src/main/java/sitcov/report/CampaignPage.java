package sitcov.report;

import java.util.List;
import java.util.Locale;
import sitcov.analysis.CampaignAnalysis;
import sitcov.experiment.CampaignConfig;
import sitcov.figures.CampaignFigure;
import sitcov.verdict.VerdictText;

/** {@code campaign.html} of a campaign of variants: the verdict, the tables per fault and pair, the figure. */
final class CampaignPage {
    private CampaignPage() {
    }

    static String html(CampaignAnalysis a, List<String> verdict) {
        CampaignConfig c = a.config();
        StringBuilder h = HtmlReport.pageStart(c.name());
        h.append("<h1>").append(HtmlReport.esc(c.name())).append("</h1><p class=\"muted\">campaign · master seed ")
                .append(c.masterSeed()).append(" · ").append(c.trials()).append(" trials per driver and fault · at most ")
                .append(c.tickBudget()).append(" ticks a trial · drivers ").append(HtmlReport.esc(String.join(", ", c.drivers())))
                .append(" · faulty runs ").append(HtmlReport.esc(c.faultyRuns().key())).append("</p>\n");
        h.append("<h2>Verdict</h2><div class=\"verdict\">");
        verdict.forEach(line -> h.append("<p>").append(HtmlReport.esc(line)).append("</p>"));
        h.append("</div>\n<h2>Per fault and driver</h2>\n");
        HtmlTable drivers = new HtmlTable("trials falsified, Kaplan–Meier median ticks to the first failure, distinct"
                + " failures (cell × accident type)", List.of(HtmlTable.Column.text("fault"), HtmlTable.Column.text("driver"),
                HtmlTable.Column.number("falsified", "falsified"), HtmlTable.Column.number("median ticks", "km_median_ticks"),
                HtmlTable.Column.number("distinct failures", "distinct_failures")));
        for (CampaignAnalysis.DriverResult r : a.drivers()) {
            drivers.row(List.of(r.target().key() + " " + r.target().label(), r.driver(), r.falsified() + " of " + r.trials(),
                    r.medianTicks().isPresent() ? Long.toString(Math.round(r.medianTicks().getAsDouble())) : "not reached",
                    Integer.toString(r.distinctFailures())));
        }
        drivers.appendTo(h);
        h.append("<h2>Pairs of drivers</h2>\n");
        HtmlTable overall = new HtmlTable("over all faults: log-rank stratified by fault (O and E: the first driver's"
                + " first failures, observed and expected under equal curves)", List.of(HtmlTable.Column.text("pair"),
                HtmlTable.Column.number("O"), HtmlTable.Column.number("E"), HtmlTable.Column.number("p"),
                HtmlTable.Column.number("Holm p")));
        for (CampaignAnalysis.Stratified s : a.stratified()) {
            overall.row(List.of(s.a() + " vs " + s.b(), VerdictText.plain(s.observedA()), VerdictText.number(s.expectedA()),
                    VerdictText.p(s.p()), VerdictText.p(s.holm())));
        }
        overall.appendTo(h);
        HtmlTable pairs = new HtmlTable("per fault: Fisher's exact test on trials falsified and log-rank on ticks to first"
                + " failure, Holm-adjusted together", List.of(HtmlTable.Column.text("fault"), HtmlTable.Column.text("pair"),
                HtmlTable.Column.number("falsified"), HtmlTable.Column.number("Fisher Holm p", "fisher_p_holm"),
                HtmlTable.Column.number("log-rank Holm p", "logrank_p_holm"), HtmlTable.Column.text("not tested")));
        for (CampaignAnalysis.PairTest t : a.pairs()) {
            pairs.row(List.of(t.fault().key(), t.a() + " vs " + t.b(),
                    String.format(Locale.ROOT, "%d vs %d", t.falsifiedA(), t.falsifiedB()), VerdictText.p(t.fisherHolm()),
                    VerdictText.p(t.logRankHolm()), t.why()));
        }
        pairs.appendTo(h);
        h.append("<h2>Figure</h2>\n<p><a href=\"").append(CampaignFigure.FILE).append("\"><img src=\"")
                .append(CampaignFigure.FILE).append("\" alt=\"trials not yet falsified against ticks\"></a></p>\n");
        h.append("<p class=\"muted\">campaign.csv has one row per fault, driver and trial; each fault's trials are an"
                + " ordinary results folder (fault-NN/runs.csv, one row per simulated run).</p></body></html>\n");
        return h.toString();
    }
}
