package sitcov.results;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import sitcov.analysis.CampaignAnalysis;
import sitcov.analysis.CampaignTrial;

/**
 * A campaign's own tables (experiments/README.md, "Campaigns: falsifying one version"): {@code campaign.csv}, one row
 * per fault, driver and trial; {@code campaign-drivers.csv}, one per fault and driver;
 * {@code campaign-stats.csv}, the tests per fault and pair and, as fault {@code ALL}, stratified by fault.
 * Numbers in full (the page rounds them); an empty cell is a value that does not exist.
 */
public final class CampaignCsv {
    public static final String TRIALS = ResultsFolder.CAMPAIGN_TRIALS;
    public static final String DRIVERS = ResultsFolder.CAMPAIGN_DRIVERS;
    public static final String STATS = ResultsFolder.CAMPAIGN_STATS;

    private CampaignCsv() {
    }

    public static List<String> trials(CampaignAnalysis a) {
        List<String> rows = new ArrayList<>();
        rows.add("fault,driver,trial,campaign_seed,stream,falsified,ticks_to_failure,survival_ticks,maps_run,stopped_by,"
                + "found_map_index,found_map,found_external_seed,found_internal_seed,found_cell,found_accident");
        for (CampaignTrial t : a.trials()) {
            String found = t.found().map(m -> m.mapIndex() + "," + m.map().text() + "," + m.externalSeed() + ","
                    + m.internalSeed() + "," + m.cell()).orElse(",,,,");
            rows.add(String.join(",", Integer.toString(t.fault().id()), t.driver(), Integer.toString(t.trial()),
                    Long.toString(t.campaignSeed()), t.streamLabel(), Boolean.toString(t.falsified()),
                    Long.toString(t.ticksToFailure()), Long.toString(t.survivalTicks()), Integer.toString(t.mapsRun()),
                    t.stop().key(), found, t.accident().map(x -> x.column()).orElse("")));
        }
        return rows;
    }

    public static List<String> drivers(CampaignAnalysis a) {
        List<String> rows = new ArrayList<>();
        rows.add("fault,driver,trials,falsified,km_median_ticks,distinct_failures");
        for (CampaignAnalysis.DriverResult r : a.drivers()) {
            rows.add(r.fault().id() + "," + r.driver() + "," + r.trials() + "," + r.falsified() + ","
                    + (r.medianTicks().isPresent() ? number(r.medianTicks().getAsDouble()) : "not reached") + ","
                    + r.distinctFailures());
        }
        return rows;
    }

    public static List<String> stats(CampaignAnalysis a) {
        List<String> rows = new ArrayList<>();
        rows.add("fault,driver_a,driver_b,falsified_a,falsified_b,fisher_p,fisher_p_holm,logrank_observed_a,"
                + "logrank_expected_a,logrank_variance,logrank_chi_square,logrank_p,logrank_p_holm,not_tested");
        for (CampaignAnalysis.PairTest t : a.pairs()) {
            rows.add(String.join(",", Integer.toString(t.fault().id()), t.a(), t.b(), Integer.toString(t.falsifiedA()),
                    Integer.toString(t.falsifiedB()), number(t.fisherP()), number(t.fisherHolm()),
                    number(t.logRank().observedA()), number(t.logRank().expectedA()), number(t.logRank().variance()),
                    number(t.logRank().chiSquare()), number(Double.isNaN(t.logRankHolm()) ? Double.NaN : t.logRank().p()),
                    number(t.logRankHolm()), t.why()));
        }
        for (CampaignAnalysis.Stratified s : a.stratified()) {
            rows.add(String.join(",", "ALL", s.a(), s.b(), "", "", "", "", number(s.observedA()), number(s.expectedA()),
                    number(s.variance()), number(s.chiSquare()), number(s.p()), number(s.holm()),
                    s.variance() == 0 ? "neither falsified any fault" : ""));
        }
        return rows;
    }

    private static String number(double v) {
        return Double.isNaN(v) ? "" : v == Math.rint(v) && Math.abs(v) < 1e15 ? Long.toString((long) v)
                : String.format(Locale.ROOT, "%.6g", v);
    }
}
