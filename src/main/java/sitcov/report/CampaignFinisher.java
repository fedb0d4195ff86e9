package sitcov.report;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import sitcov.analysis.CampaignAnalysis;
import sitcov.analysis.CampaignTrial;
import sitcov.experiment.CampaignConfig;
import sitcov.experiment.DriverRun;
import sitcov.experiment.Journal;
import sitcov.experiment.ReplicationResult;
import sitcov.experiment.SeedPlan;
import sitcov.judge.Variant;
import sitcov.figures.CampaignFigure;
import sitcov.results.CampaignCsv;
import sitcov.results.CampaignManifest;
import sitcov.results.FolderLock;
import sitcov.results.JournalFiles;
import sitcov.results.Manifest;
import sitcov.results.OutputFile;
import sitcov.results.ResultsFolder;
import sitcov.experiment.Shard;
import sitcov.verdict.CampaignVerdict;
import sitcov.verdict.VerdictText;

/**
 * Completes a campaign's results folder from its faults' sub-folders (experiments/README.md, "Campaigns: falsifying
 * one version"): campaign.csv and its other tables, the verdict, the figure and campaign.html. Only the
 * sub-folders' journals are read, so a run, a resumed run and a report write the same bytes.
 */
public final class CampaignFinisher {
    public static final String PAGE = ResultsFolder.CAMPAIGN_PAGE;

    private CampaignFinisher() {
    }

    /** Writes every file of the campaign and marks its manifest complete. */
    public static CampaignAnalysis finish(Path folder, CampaignManifest manifest) throws IOException {
        CampaignAnalysis a = analyse(folder, manifest.config());
        OutputFile.writeLines(folder.resolve(CampaignCsv.TRIALS), CampaignCsv.trials(a));
        OutputFile.writeLines(folder.resolve(CampaignCsv.DRIVERS), CampaignCsv.drivers(a));
        OutputFile.writeLines(folder.resolve(CampaignCsv.STATS), CampaignCsv.stats(a));
        List<String> verdict = CampaignVerdict.lines(a);
        OutputFile.writeLines(folder.resolve(ResultsFolder.VERDICT), verdict);
        CampaignFigure.write(a, folder);
        OutputFile.writeString(folder.resolve(PAGE), page(a, verdict));
        manifest.complete(true).write(folder);
        return a;
    }

    /**
     * Writes a complete campaign's own files again from its sub-folders, holding its lock meanwhile.
     *
     * @throws IllegalArgumentException when the campaign is incomplete or a sub-folder was changed by hand
     * @throws IllegalStateException when a run holds the folder
     */
    public static CampaignAnalysis report(Path folder) throws IOException {
        CampaignManifest manifest = CampaignManifest.read(folder);
        if (!manifest.complete()) {
            throw new IllegalArgumentException(folder + " is not complete; finish it with 'run --resume " + folder + "'");
        }
        try (FolderLock lock = FolderLock.claim(folder)) {
            ResultsFolder.sweepTemporaries(folder);
            return finish(folder, manifest);
        }
    }

    /**
     * The campaign's trials, read from each fault's complete sub-folder.
     *
     * @throws IllegalArgumentException when a sub-folder is missing, incomplete, changed by hand or of another campaign
     */
    public static CampaignAnalysis analyse(Path folder, CampaignConfig c) throws IOException {
        List<CampaignTrial> trials = new ArrayList<>();
        for (Variant f : c.variants()) {
            Path sub = folder.resolve(CampaignConfig.folderOf(f));
            Manifest m = Manifest.read(sub);
            check(m, c, f, folder);
            if (!m.complete()) {
                throw new IllegalArgumentException(sub + " is not complete; finish the campaign with 'run --resume " + folder
                        + "'");
            }
            Journal journal = JournalFiles.read(sub, m);
            for (ReplicationResult r : ResultsFinisher.results(m, journal)) {
                for (DriverRun d : r.drivers()) {
                    trials.add(CampaignTrial.of(f, r.replication(), m.config().masterSeed(),
                            SeedPlan.replicationLabel(r.replication()), c.tickBudget(), d));
                }
            }
        }
        trials.sort(Comparator.comparingInt((CampaignTrial t) -> t.fault().id()).thenComparingInt(t -> c.drivers().indexOf(t.driver()))
                .thenComparingInt(CampaignTrial::trial));
        return CampaignAnalysis.of(c, trials);
    }

    /** Refuses the sub-folder of {@code campaign} that is not the experiment the campaign implies for {@code fault}. */
    public static void check(Manifest m, CampaignConfig c, Variant fault, Path campaign) {
        Manifest expected = new Manifest(c.trialsOf(fault), m.version(), Shard.WHOLE, m.complete(), m.resumed());
        if (!expected.identity().equals(m.identity()) || !m.shard().isWhole()) {
            throw new IllegalArgumentException(campaign.resolve(CampaignConfig.folderOf(fault)) + " holds another experiment"
                    + " than this campaign's trials of fault " + fault.id() + " (its manifest differs); put back the folder"
                    + " the campaign wrote, or run the campaign again into a new folder: " + Manifest.again(campaign));
        }
    }

    private static String page(CampaignAnalysis a, List<String> verdict) {
        CampaignConfig c = a.config();
        StringBuilder h = new StringBuilder();
        h.append("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">")
                .append("<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">")
                .append("<title>sitcov: ").append(HtmlReport.esc(c.name())).append("</title><style>").append(HtmlReport.CSS)
                .append("</style></head><body>\n");
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
            drivers.row(List.of(r.fault().id() + " " + r.fault().label(), r.driver(), r.falsified() + " of " + r.trials(),
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
            pairs.row(List.of(Integer.toString(t.fault().id()), t.a() + " vs " + t.b(),
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
