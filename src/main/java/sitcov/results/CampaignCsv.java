package sitcov.results;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.OptionalDouble;
import sitcov.analysis.CampaignAnalysis;
import sitcov.analysis.CampaignTrial;
import sitcov.analysis.PairedTrials;
import sitcov.experiment.CampaignConfig;
import sitcov.experiment.CampaignTarget;
import sitcov.experiment.StopReason;
import sitcov.oracle.Failure;

/**
 * A campaign's own tables (experiments/README.md, "Campaigns: falsifying one version"): {@code campaign.csv}, one row
 * per target, driver and trial; {@code campaign-drivers.csv}, one per target and driver;
 * {@code campaign-stats.csv}, the tests per target and pair and, in a campaign of faults, as fault {@code ALL},
 * stratified by fault. A campaign of requirements names its targets in a column {@code requirement}, and its
 * tables carry the intervals and paired tests of its analysis.
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
        rows.add(trialsHeader(a.config()));
        for (CampaignTrial t : a.trials()) {
            String found = t.found().map(m -> m.mapIndex() + "," + m.map() + "," + m.externalSeed() + ","
                    + m.internalSeed() + "," + m.cell()).orElse(",,,,");
            rows.add(String.join(",", t.target().key(), t.driver(), Integer.toString(t.trial()),
                    Long.toString(t.campaignSeed()), t.streamLabel(), Boolean.toString(t.falsified()),
                    Long.toString(t.ticksToFailure()), Long.toString(t.survivalTicks()), Integer.toString(t.mapsRun()),
                    t.stop().key(), found, t.accident().map(x -> x.column()).orElse("")));
        }
        return rows;
    }

    private static String trialsHeader(CampaignConfig c) {
        return c.targets().get(0).column() + ",driver,trial,campaign_seed,stream,falsified,ticks_to_failure,survival_ticks,"
                + "maps_run,stopped_by,found_map_index,found_map,found_external_seed,found_internal_seed,found_cell,found_accident";
    }

    /**
     * The trials of campaign {@code c} as {@link #trials} wrote them, the {@code lines} of {@code file}, so that a folder that keeps
     * only campaign.csv of its sub-folders can still have its other tables computed again.
     *
     * @throws IllegalArgumentException when the file is not such a campaign.csv of {@code c}
     */
    public static List<CampaignTrial> readTrials(CampaignConfig c, Path file, List<String> lines) {
        if (lines.isEmpty() || !lines.get(0).equals(trialsHeader(c))) {
            throw new IllegalArgumentException(file + " is not the campaign.csv of this campaign (its header differs);"
                    + " put back the file the campaign wrote");
        }
        List<CampaignTrial> trials = new ArrayList<>();
        for (int i = 1; i < lines.size(); i++) {
            try {
                trials.add(trial(c, lines.get(i)));
            } catch (RuntimeException e) {
                throw new IllegalArgumentException(file + ", row " + (i + 1) + ", is not a trial this campaign wrote ("
                        + e.getMessage() + "); put back the file the campaign wrote");
            }
        }
        return trials;
    }

    private static CampaignTrial trial(CampaignConfig c, String line) {
        String[] f = line.split(",", -1);
        if (f.length != 16) {
            throw new IllegalArgumentException(f.length + " cells where there are 16");
        }
        CampaignTarget target = c.targets().stream().filter(t -> t.key().equals(f[0])).findFirst()
                .orElseThrow(() -> new IllegalArgumentException("no target " + f[0]));
        if (!c.drivers().contains(f[1])) {
            throw new IllegalArgumentException("no driver " + f[1]);
        }
        Optional<CampaignTrial.FoundMap> found = f[10].isEmpty() ? Optional.empty()
                : Optional.of(new CampaignTrial.FoundMap(Integer.parseInt(f[10]), f[11], Long.parseLong(f[12]),
                        Long.parseLong(f[13]), Integer.parseInt(f[14])));
        Optional<Failure> accident = f[15].isEmpty() ? Optional.empty()
                : Optional.of(Failure.valueOf(f[15].toUpperCase(Locale.ROOT)));
        return new CampaignTrial(target, f[1], Integer.parseInt(f[2]), Long.parseLong(f[3]), f[4],
                Boolean.parseBoolean(f[5]), Long.parseLong(f[6]), Long.parseLong(f[7]), Integer.parseInt(f[8]),
                StopReason.ofKey(f[9]), found, accident);
    }

    public static List<String> drivers(CampaignAnalysis a) {
        if (a.config().onRequirements()) {
            return requirementDrivers(a);
        }
        List<String> rows = new ArrayList<>();
        rows.add("fault,driver,trials,falsified,km_median_ticks,distinct_failures");
        for (CampaignAnalysis.DriverResult r : a.drivers()) {
            rows.add(r.target().key() + "," + r.driver() + "," + r.trials() + "," + r.falsified() + ","
                    + (r.medianTicks().isPresent() ? number(r.medianTicks().getAsDouble()) : "not reached") + ","
                    + r.distinctFailures());
        }
        return rows;
    }

    public static List<String> stats(CampaignAnalysis a) {
        if (a.config().onRequirements()) {
            return requirementStats(a);
        }
        List<String> rows = new ArrayList<>();
        rows.add("fault,driver_a,driver_b,falsified_a,falsified_b,fisher_p,fisher_p_holm,logrank_observed_a,"
                + "logrank_expected_a,logrank_variance,logrank_chi_square,logrank_p,logrank_p_holm,not_tested");
        for (CampaignAnalysis.PairTest t : a.pairs()) {
            rows.add(String.join(",", t.fault().key(), t.a(), t.b(), Integer.toString(t.falsifiedA()),
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

    private static List<String> requirementDrivers(CampaignAnalysis a) {
        List<String> rows = new ArrayList<>();
        rows.add("requirement,driver,trials,falsified,falsified_share,falsified_ci_low,falsified_ci_high,km_median_ticks,"
                + "km_median_ci_low,km_median_ci_high,mean_ticks_to_failure,median_maps_to_failure,mean_maps_to_failure,"
                + "distinct_failures");
        for (CampaignAnalysis.DriverResult r : a.drivers()) {
            rows.add(String.join(",", r.target().key(), r.driver(), Integer.toString(r.trials()),
                    Integer.toString(r.falsified()), number(r.share().estimate()), number(r.share().low()),
                    number(r.share().high()), reached(r.medianTicks()), reached(r.medianInterval().low()),
                    reached(r.medianInterval().high()), number(r.meanTicks()), number(r.medianMaps()),
                    number(r.meanMaps()), Integer.toString(r.distinctFailures())));
        }
        return rows;
    }

    private static List<String> requirementStats(CampaignAnalysis a) {
        List<String> rows = new ArrayList<>();
        rows.add("requirement,driver_a,driver_b,falsified_a,falsified_b,only_a,only_b,mcnemar_p,mcnemar_p_holm,first_a,"
                + "first_b,logrank_observed_a,logrank_expected_a,logrank_variance,logrank_p,logrank_p_holm,not_tested");
        for (PairedTrials t : a.paired()) {
            rows.add(String.join(",", t.target().key(), t.a(), t.b(), Integer.toString(t.falsifiedA()),
                    Integer.toString(t.falsifiedB()), Integer.toString(t.onlyA()), Integer.toString(t.onlyB()),
                    number(t.mcNemarP()), number(t.mcNemarHolm()), Integer.toString(t.logRank().firstA()),
                    Integer.toString(t.logRank().firstB()), number(t.logRank().observedA()),
                    number(t.logRank().expectedA()), number(t.logRank().variance()), number(t.logRankP()),
                    number(t.logRankHolm()), t.why()));
        }
        return rows;
    }

    /** A median or an end of its interval: {@code not reached} where the curve never falls that far. */
    private static String reached(OptionalDouble v) {
        return v.isPresent() ? number(v.getAsDouble()) : "not reached";
    }

    private static String number(OptionalDouble v) {
        return v.isPresent() ? number(v.getAsDouble()) : "";
    }

    private static String number(double v) {
        return Double.isNaN(v) ? "" : v == Math.rint(v) && Math.abs(v) < 1e15 ? Long.toString((long) v)
                : String.format(Locale.ROOT, "%.6g", v);
    }
}
