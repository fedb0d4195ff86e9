package sitcov.analysis;

import java.util.ArrayList;
import java.util.List;
import sitcov.experiment.AnalysisPlan;
import sitcov.experiment.CampaignConfig;
import sitcov.experiment.CampaignTarget;
import sitcov.stats.Holm;
import sitcov.stats.McNemar;
import sitcov.stats.PairedLogRank;

/**
 * Two drivers on one target of a campaign, paired by trial: every driver of trial t reads the same candidate
 * stream, so trial t of A and trial t of B are a pair. McNemar's exact test on falsified, from the trials only A
 * falsified against those only B did; the log-rank test stratified by trial on ticks to first failure
 * ({@link PairedLogRank}: the exact sign test on which of the two falsified first). A test whose discordant
 * trials are too few for any split of them to reach {@link AnalysisPlan#ALPHA} (fewer than 6) is not made: its p
 * is NaN and {@code why} says so (no comma in it: it is a cell of a CSV file). The tests made, over every target and pair, are one family under Holm.
 */
public record PairedTrials(CampaignTarget target, String a, String b, int falsifiedA, int falsifiedB, int onlyA,
                           int onlyB, double mcNemarP, double mcNemarHolm, PairedLogRank.Result logRank,
                           double logRankHolm, String why) {
    /** The log-rank test's p before adjustment; NaN where it was not made. */
    public double logRankP() {
        return Double.isNaN(logRankHolm) ? Double.NaN : logRank.p();
    }

    /** Whether a test on {@code discordant} pairs can reach the level at all. */
    static boolean reaches(int discordant) {
        return McNemar.smallestP(discordant) <= AnalysisPlan.ALPHA;
    }

    static List<PairedTrials> of(CampaignConfig config, List<CampaignTrial> trials, List<String[]> pairs) {
        record Raw(CampaignTarget f, String a, String b, int fa, int fb, int onlyA, int onlyB, double mcNemar,
                   PairedLogRank.Result lr, String why) {
        }
        List<Raw> raw = new ArrayList<>();
        List<Double> family = new ArrayList<>();
        for (CampaignTarget f : config.targets()) {
            for (String[] p : pairs) {
                List<CampaignTrial> a = CampaignAnalysis.of(trials, f, p[0]);
                List<CampaignTrial> b = CampaignAnalysis.of(trials, f, p[1]);
                int onlyA = 0;
                int onlyB = 0;
                for (int t = 0; t < a.size(); t++) {
                    onlyA += a.get(t).falsified() && !b.get(t).falsified() ? 1 : 0;
                    onlyB += b.get(t).falsified() && !a.get(t).falsified() ? 1 : 0;
                }
                PairedLogRank.Result lr = PairedLogRank.test(CampaignTrial.observations(a), CampaignTrial.observations(b));
                double mcNemar = reaches(onlyA + onlyB) ? McNemar.exactP(onlyA, onlyB) : Double.NaN;
                List<String> why = new ArrayList<>();
                if (Double.isNaN(mcNemar)) {
                    why.add("McNemar: " + (onlyA + onlyB) + " trial" + (onlyA + onlyB == 1 ? "" : "s")
                            + " falsified by one driver only: cannot reach " + AnalysisPlan.ALPHA);
                } else {
                    family.add(mcNemar);
                }
                if (reaches(lr.informative())) {
                    family.add(lr.p());
                } else {
                    why.add("log-rank: " + lr.informative() + " trial" + (lr.informative() == 1 ? "" : "s")
                            + " with one driver first: cannot reach " + AnalysisPlan.ALPHA);
                }
                raw.add(new Raw(f, p[0], p[1], falsified(a), falsified(b), onlyA, onlyB, mcNemar, lr,
                        String.join("; ", why)));
            }
        }
        double[] adjusted = Holm.adjust(family.stream().mapToDouble(Double::doubleValue).toArray());
        List<PairedTrials> out = new ArrayList<>();
        int k = 0;
        for (Raw r : raw) {
            double mcNemarHolm = Double.isNaN(r.mcNemar()) ? Double.NaN : adjusted[k++];
            double lrHolm = reaches(r.lr().informative()) ? adjusted[k++] : Double.NaN;
            out.add(new PairedTrials(r.f(), r.a(), r.b(), r.fa(), r.fb(), r.onlyA(), r.onlyB(), r.mcNemar(), mcNemarHolm,
                    r.lr(), lrHolm, r.why()));
        }
        return out;
    }

    private static int falsified(List<CampaignTrial> trials) {
        return (int) trials.stream().filter(CampaignTrial::falsified).count();
    }
}
