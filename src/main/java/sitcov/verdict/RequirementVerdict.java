package sitcov.verdict;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.OptionalDouble;
import sitcov.analysis.CampaignAnalysis;
import sitcov.analysis.PairedTrials;
import sitcov.experiment.AnalysisPlan;
import sitcov.experiment.CampaignConfig;

/**
 * The verdict of a campaign of the reference's own requirements (experiments/README.md, "Requirement campaigns:
 * where your controller itself fails"), as ARCH-COMP reports falsification: per requirement and driver how many
 * trials falsified it, with intervals, and how soon; per driver the requirements falsified; then the paired tests of
 * each pair of drivers per requirement, one Holm family, those that cannot reach the level described instead.
 */
public final class RequirementVerdict {
    private RequirementVerdict() {
    }

    public static List<String> lines(CampaignAnalysis a) {
        CampaignConfig c = a.config();
        List<String> lines = new ArrayList<>();
        lines.add(String.format(Locale.ROOT, "Campaign %s: the requirements of %s, each its own campaign: %d trial%s per"
                + " driver and requirement, at most %d simulated ticks a trial; a trial stops at its first map on which"
                + " the controller violates the requirement. Intervals are 95 %%: Wilson's for the share of trials"
                + " falsified, Brookmeyer and Crowley's for the Kaplan-Meier median; means and medians of ticks and maps"
                + " are over the falsified trials only.", c.name(), c.controller(), c.trials(), c.trials() == 1 ? "" : "s",
                c.tickBudget()));
        for (CampaignAnalysis.DriverResult r : a.drivers()) {
            lines.add(driver(r));
        }
        for (CampaignAnalysis.Overall o : a.overall()) {
            lines.add(String.format(Locale.ROOT, "%s falsified %d of the %d requirements in at least one trial, %d in a"
                    + " majority of its trials.", o.driver(), o.anyTrial(), o.faults(), o.majority()));
        }
        if (!a.paired().isEmpty()) {
            lines.add(family(a.paired()));
            a.paired().forEach(t -> lines.add("- " + pair(t)));
        }
        return lines;
    }

    private static String driver(CampaignAnalysis.DriverResult r) {
        String head = String.format(Locale.ROOT, "%s, %s: falsified in %d of %d trials (%s to %s)", r.target().key(),
                r.driver(), r.falsified(), r.trials(), percent(r.share().low()), percent(r.share().high()));
        if (r.falsified() == 0) {
            return head + "; the median is not reached: no trial violated it within its budget.";
        }
        return head + String.format(Locale.ROOT, "; median ticks to the first failure %s (%s to %s); over the %d falsified:"
                + " %s ticks and %s maps on average, median %s maps.", ticks(r.medianTicks()),
                ticks(r.medianInterval().low()), ticks(r.medianInterval().high()), r.falsified(),
                ticks(r.meanTicks()), VerdictText.number(r.meanMaps().getAsDouble()),
                VerdictText.plain(r.medianMaps().getAsDouble()));
    }

    private static String family(List<PairedTrials> tests) {
        long made = tests.stream().mapToLong(t -> (Double.isNaN(t.mcNemarP()) ? 0 : 1) + (Double.isNaN(t.logRankP()) ? 0 : 1))
                .sum();
        return "Paired by trial (every driver of a trial reads the same candidates), per requirement and pair of drivers:"
                + " McNemar's exact test on falsified, and the log-rank test stratified by trial on ticks to the first"
                + " failure (with two trials a stratum, the exact sign test on which driver falsified first); " + made
                + " test" + (made == 1 ? "" : "s") + " made, Holm-adjusted together. A test on fewer than 6 trials that"
                + " tell the drivers apart cannot reach p < " + AnalysisPlan.ALPHA + " whichever way they fall, so it is"
                + " described and not made. No difference shown is not evidence that the drivers are equal.";
    }

    private static String pair(PairedTrials t) {
        if (t.falsifiedA() + t.falsifiedB() == 0) {
            return t.target().key() + ", " + t.a() + " against " + t.b() + ": neither falsified it in any trial.";
        }
        String often = String.format(Locale.ROOT, "falsified in %d against %d trials (only %s in %d, only %s in %d", t.falsifiedA(),
                t.falsifiedB(), t.a(), t.onlyA(), t.b(), t.onlyB());
        if (Double.isNaN(t.mcNemarP())) {
            often += ": cannot reach " + AnalysisPlan.ALPHA + ")";
        } else {
            often += shown(t.mcNemarHolm(), t.onlyA() > t.onlyB() ? t.a() : t.b(), "falsifies more often",
                    "McNemar Holm p = ") + ")";
        }
        String soon = String.format(Locale.ROOT, "first to falsify in %d against %d trials", t.logRank().firstA(),
                t.logRank().firstB());
        if (Double.isNaN(t.logRankP())) {
            soon += " (cannot reach " + AnalysisPlan.ALPHA + ")";
        } else {
            soon += " (" + shown(t.logRankHolm(), t.logRank().firstA() > t.logRank().firstB() ? t.a() : t.b(),
                    "falsifies sooner", "log-rank by trial Holm p = ").substring(2) + ")";
        }
        return t.target().key() + ", " + t.a() + " against " + t.b() + ": " + often + "; " + soon + ".";
    }

    private static String shown(double holm, String ahead, String what, String test) {
        return holm <= AnalysisPlan.ALPHA ? "; " + ahead + " " + what + ", " + test + VerdictText.p(holm)
                : "; no difference shown, " + test + VerdictText.p(holm);
    }

    private static String percent(double share) {
        return String.format(Locale.ROOT, "%.0f %%", 100 * share);
    }

    private static String ticks(OptionalDouble v) {
        return v.isPresent() ? Long.toString(Math.round(v.getAsDouble())) : "not reached";
    }
}
