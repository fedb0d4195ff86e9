package sitcov.analysis;

import java.util.ArrayList;
import java.util.List;
import java.util.OptionalDouble;
import sitcov.experiment.CampaignConfig;
import sitcov.experiment.CampaignTarget;
import sitcov.stats.ConfidenceInterval;
import sitcov.stats.FisherExact;
import sitcov.stats.Holm;
import sitcov.stats.KaplanMeier;
import sitcov.stats.LogRank;
import sitcov.stats.Normal;
import sitcov.stats.Wilson;

/**
 * The statistics of a campaign (experiments/README.md, "Campaigns: falsifying one version"), from its trials: per
 * target and driver, the trials falsified and the Kaplan–Meier median ticks to the first failure. A campaign of
 * variants: per fault and pair of drivers, Fisher's exact test on the trials falsified and the log-rank test on the
 * ticks to first failure, Holm-adjusted together as one family; over all faults, per driver the
 * faults falsified, and per pair a log-rank test stratified by fault, Holm-adjusted over the pairs. A campaign
 * of requirements: per requirement and pair the paired tests of {@link PairedTrials}.
 */
public record CampaignAnalysis(CampaignConfig config, List<CampaignTrial> trials, List<DriverResult> drivers,
                               List<PairTest> pairs, List<Stratified> stratified, List<Overall> overall,
                               List<PairedTrials> paired) {
    /**
     * One driver on one target: trials falsified of {@code trials} with the share's 95 % Wilson interval, the KM
     * median (empty: not reached) with its 95 % Brookmeyer–Crowley interval, distinct failures, the curve; over
     * its falsified trials only (empty when none), the mean ticks and the median and mean maps to the failure.
     */
    public record DriverResult(CampaignTarget target, String driver, int falsified, int trials, OptionalDouble medianTicks,
                               int distinctFailures, List<KaplanMeier.Step> curve, ConfidenceInterval share,
                               KaplanMeier.MedianInterval medianInterval, OptionalDouble meanTicks,
                               OptionalDouble medianMaps, OptionalDouble meanMaps) {
    }

    /**
     * A pair of drivers on one fault. A test is left out of the family (its p NaN, {@code why} says why)
     * when it cannot tell the two apart whatever happened: Fisher when both falsified every trial or none,
     * the log-rank test when no trial of either was falsified.
     */
    public record PairTest(CampaignTarget fault, String a, String b, int falsifiedA, int falsifiedB, double fisherP,
                           double fisherHolm, LogRank.Result logRank, double logRankHolm, String why) {
    }

    /** A pair over all faults: the log-rank sums over the faults (strata), its p and the Holm-adjusted p. */
    public record Stratified(String a, String b, double observedA, double expectedA, double variance, double chiSquare,
                             double p, double holm) {
        /** Whether A had more first failures than equal curves would give it (it falsifies sooner). */
        public boolean aSooner() {
            return observedA > expectedA;
        }
    }

    /** A driver over all faults: faults falsified in at least one trial, and in more than half of them. */
    public record Overall(String driver, int anyTrial, int majority, int faults) {
    }

    public static CampaignAnalysis of(CampaignConfig config, List<CampaignTrial> trials) {
        List<DriverResult> drivers = new ArrayList<>();
        double z = Normal.quantile(0.975);
        for (CampaignTarget f : config.targets()) {
            for (String d : config.drivers()) {
                List<CampaignTrial> mine = of(trials, f, d);
                List<KaplanMeier.Step> curve = KaplanMeier.curve(CampaignTrial.observations(mine));
                List<CampaignTrial> hits = mine.stream().filter(CampaignTrial::falsified).toList();
                int distinct = (int) mine.stream().flatMap(t -> t.failure().stream()).distinct().count();
                drivers.add(new DriverResult(f, d, hits.size(), mine.size(), KaplanMeier.median(curve), distinct, curve,
                        Wilson.interval(hits.size(), mine.size()), KaplanMeier.medianInterval(curve, z),
                        hits.stream().mapToLong(CampaignTrial::ticksToFailure).average(),
                        median(hits.stream().mapToDouble(CampaignTrial::mapsRun).sorted().toArray()),
                        hits.stream().mapToInt(CampaignTrial::mapsRun).average()));
            }
        }
        List<String[]> pairs = new ArrayList<>();
        for (int i = 0; i < config.drivers().size(); i++) {
            for (int j = i + 1; j < config.drivers().size(); j++) {
                pairs.add(new String[] {config.drivers().get(i), config.drivers().get(j)});
            }
        }
        if (config.onRequirements()) {
            return new CampaignAnalysis(config, List.copyOf(trials), drivers, List.of(), List.of(), overall(config, drivers),
                    PairedTrials.of(config, trials, pairs));
        }
        return new CampaignAnalysis(config, List.copyOf(trials), drivers, pairTests(config, trials, pairs),
                stratified(config, trials, pairs), overall(config, drivers), List.of());
    }

    private static OptionalDouble median(double[] sorted) {
        int n = sorted.length;
        return n == 0 ? OptionalDouble.empty() : OptionalDouble.of((sorted[(n - 1) / 2] + sorted[n / 2]) / 2);
    }

    private static List<PairTest> pairTests(CampaignConfig config, List<CampaignTrial> trials, List<String[]> pairs) {
        record Raw(CampaignTarget f, String a, String b, int fa, int fb, double fisher, LogRank.Result lr, String why) {
        }
        List<Raw> raw = new ArrayList<>();
        List<Double> family = new ArrayList<>();
        for (CampaignTarget f : config.targets()) {
            for (String[] p : pairs) {
                List<CampaignTrial> a = of(trials, f, p[0]);
                List<CampaignTrial> b = of(trials, f, p[1]);
                int fa = falsified(a);
                int fb = falsified(b);
                boolean fisherTestable = !(fa + fb == 0 || (fa == a.size() && fb == b.size()));
                double fisher = fisherTestable ? FisherExact.twoSidedP(fa, a.size() - fa, fb, b.size() - fb) : Double.NaN;
                LogRank.Result lr = LogRank.test(CampaignTrial.observations(a), CampaignTrial.observations(b));
                boolean lrTestable = fa + fb > 0 && lr.variance() > 0;
                String why = fa + fb == 0 ? "neither falsified it" : fisherTestable ? "" : "both falsified every trial";
                raw.add(new Raw(f, p[0], p[1], fa, fb, fisher, lr, why));
                if (fisherTestable) {
                    family.add(fisher);
                }
                if (lrTestable) {
                    family.add(lr.p());
                }
            }
        }
        double[] adjusted = Holm.adjust(family.stream().mapToDouble(Double::doubleValue).toArray());
        List<PairTest> out = new ArrayList<>();
        int k = 0;
        for (Raw r : raw) {
            double fisherHolm = Double.isNaN(r.fisher()) ? Double.NaN : adjusted[k++];
            double lrHolm = r.fa() + r.fb() > 0 && r.lr().variance() > 0 ? adjusted[k++] : Double.NaN;
            out.add(new PairTest(r.f(), r.a(), r.b(), r.fa(), r.fb(), r.fisher(), fisherHolm, r.lr(), lrHolm, r.why()));
        }
        return out;
    }

    /** The log-rank test stratified by fault: (Σ O − Σ E)² / Σ V, each sum over the faults' strata. */
    private static List<Stratified> stratified(CampaignConfig config, List<CampaignTrial> trials, List<String[]> pairs) {
        List<double[]> sums = new ArrayList<>();
        for (String[] p : pairs) {
            double o = 0;
            double e = 0;
            double v = 0;
            for (CampaignTarget f : config.targets()) {
                LogRank.Result r = LogRank.test(CampaignTrial.observations(of(trials, f, p[0])),
                        CampaignTrial.observations(of(trials, f, p[1])));
                o += r.observedA();
                e += r.expectedA();
                v += r.variance();
            }
            double chi = v == 0 ? 0 : (o - e) * (o - e) / v;
            sums.add(new double[] {o, e, v, chi, v == 0 ? 1 : 2 * Normal.upperTail(Math.sqrt(chi))});
        }
        double[] holm = Holm.adjust(sums.stream().mapToDouble(s -> s[4]).toArray());
        List<Stratified> out = new ArrayList<>();
        for (int i = 0; i < pairs.size(); i++) {
            double[] s = sums.get(i);
            out.add(new Stratified(pairs.get(i)[0], pairs.get(i)[1], s[0], s[1], s[2], s[3], s[4], holm[i]));
        }
        return out;
    }

    private static List<Overall> overall(CampaignConfig config, List<DriverResult> drivers) {
        List<Overall> out = new ArrayList<>();
        for (String d : config.drivers()) {
            List<DriverResult> mine = drivers.stream().filter(r -> r.driver().equals(d)).toList();
            int any = (int) mine.stream().filter(r -> r.falsified() > 0).count();
            int majority = (int) mine.stream().filter(r -> 2 * r.falsified() > r.trials()).count();
            out.add(new Overall(d, any, majority, mine.size()));
        }
        return out;
    }

    /** The trials of {@code driver} on {@code target}, in trial order. */
    public static List<CampaignTrial> of(List<CampaignTrial> trials, CampaignTarget target, String driver) {
        return trials.stream().filter(t -> t.target().equals(target) && t.driver().equals(driver))
                .sorted(java.util.Comparator.comparingInt(CampaignTrial::trial)).toList();
    }

    private static int falsified(List<CampaignTrial> trials) {
        return (int) trials.stream().filter(CampaignTrial::falsified).count();
    }
}
