package sitcov.verdict;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import sitcov.analysis.CampaignAnalysis;
import sitcov.experiment.AnalysisPlan;
import sitcov.experiment.CampaignConfig;
import sitcov.stats.FisherExact;

/**
 * A campaign's verdict in plain sentences (experiments/README.md, "Campaigns: falsifying one version"): what each
 * driver falsified, then per pair the stratified log-rank test over all faults, then the per-fault tests
 * that show a difference after Holm's adjustment. Like the suites' verdict it claims no more than the
 * tests show: a test that shows nothing is "no difference shown", never "equal".
 */
public final class CampaignVerdict {
    private CampaignVerdict() {
    }

    public static List<String> lines(CampaignAnalysis a) {
        CampaignConfig c = a.config();
        List<String> lines = new ArrayList<>();
        lines.add(String.format(Locale.ROOT, "Campaign %s: %d trial%s per driver and fault, at most %d simulated ticks a"
                + " trial, %d fault%s each its own campaign; a trial stops at its first map on which the differential"
                + " oracle finds its fault.", c.name(), c.trials(), c.trials() == 1 ? "" : "s", c.tickBudget(),
                c.variants().size(), c.variants().size() == 1 ? "" : "s"));
        for (CampaignAnalysis.Overall o : a.overall()) {
            lines.add(String.format(Locale.ROOT, "%s falsified %d of the %d faults in at least one trial, %d in a majority"
                    + " of its trials.", o.driver(), o.anyTrial(), o.faults(), o.majority()));
        }
        for (CampaignAnalysis.Stratified s : a.stratified()) {
            lines.add(stratified(s, a.stratified().size()));
        }
        lines.add(perFault(a));
        return lines;
    }

    private static String stratified(CampaignAnalysis.Stratified s, int pairs) {
        String holm = pairs > 1 ? "Holm p over " + pairs + " pairs = " + VerdictText.p(s.holm()) : "p = " + VerdictText.p(s.p());
        if (s.variance() == 0) {
            return "Over all faults, " + s.a() + " against " + s.b() + ": not testable, neither falsified any fault.";
        }
        String sums = String.format(Locale.ROOT, "%s had %s first failures where equal curves give %s", s.a(),
                VerdictText.plain(s.observedA()), VerdictText.number(s.expectedA()));
        if (s.holm() <= AnalysisPlan.ALPHA) {
            String sooner = s.aSooner() ? s.a() : s.b();
            String later = s.aSooner() ? s.b() : s.a();
            return "Over all faults, " + sooner + " falsifies sooner than " + later + " (log-rank stratified by fault: "
                    + sums + "; " + holm + ").";
        }
        return "Over all faults, no difference in ticks to first failure is shown between " + s.a() + " and " + s.b()
                + " (log-rank stratified by fault: " + sums + "; " + holm + "); that is not evidence that they are equal.";
    }

    private static String perFault(CampaignAnalysis a) {
        List<String> shown = new ArrayList<>();
        int tested = 0;
        for (CampaignAnalysis.PairTest t : a.pairs()) {
            tested += (Double.isNaN(t.fisherHolm()) ? 0 : 1) + (Double.isNaN(t.logRankHolm()) ? 0 : 1);
            boolean fisher = t.fisherHolm() <= AnalysisPlan.ALPHA;
            boolean logRank = t.logRankHolm() <= AnalysisPlan.ALPHA;
            if (fisher || logRank) {
                boolean aAhead = logRank ? t.logRank().observedA() > t.logRank().expectedA() : t.falsifiedA() > t.falsifiedB();
                String ahead = aAhead ? t.a() : t.b();
                String behind = aAhead ? t.b() : t.a();
                shown.add(String.format(Locale.ROOT, "fault %s: %s ahead of %s (%d against %d trials falsified%s%s)",
                        t.fault().key(), ahead, behind, aAhead ? t.falsifiedA() : t.falsifiedB(),
                        aAhead ? t.falsifiedB() : t.falsifiedA(),
                        fisher ? ", Fisher Holm p = " + VerdictText.p(t.fisherHolm()) : "",
                        logRank ? ", log-rank Holm p = " + VerdictText.p(t.logRankHolm()) : ""));
            }
        }
        int n = a.config().trials();
        String family = "Per fault, Fisher's exact test on trials falsified and the log-rank test on ticks to first failure ("
                + tested + " tests, Holm-adjusted together; Fisher's test leaves out a fault that neither driver falsified or both"
                + " did in every trial, the log-rank test one that neither falsified)";
        if (shown.isEmpty()) {
            return family + ": no difference shown for any fault; with " + n + " trials a driver even " + n + " of " + n
                    + " against 0 of " + n + " falsified gives Fisher p = " + VerdictText.p(FisherExact.twoSidedP(n, 0, 0, n))
                    + " before adjustment.";
        }
        return family + ": a difference shown for " + String.join("; ", shown) + "; for the others no difference shown.";
    }
}
