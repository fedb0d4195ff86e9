package sitcov.verdict;

import static sitcov.verdict.VerdictText.number;
import static sitcov.verdict.VerdictText.p;
import static sitcov.verdict.VerdictText.signed;

import sitcov.analysis.Finding;
import sitcov.analysis.MeasureComparison;
import sitcov.analysis.PairedDifference;
import sitcov.experiment.AnalysisPlan;

/**
 * The one sentence that answers a preset's primary question, with the numbers in the order the
 * question names the drivers: yes or no where a difference or equivalence is shown, "inconclusive"
 * with what the data still allow and what could have been detected, "no difference tested" where too
 * few replications differ for the test to reach the level.
 */
final class PrimaryAnswer {
    private PrimaryAnswer() {
    }

    static String of(MeasureComparison m, AnalysisPlan plan) {
        String first = plan.primaryDrivers().get(0);
        String second = plan.primaryDrivers().get(1);
        boolean asNamed = first.equals(m.driverA());
        PairedDifference d = m.paired();
        double sign = asNamed ? 1 : -1;
        double low = asNamed ? d.difference().low() : -d.difference().high();
        double high = asNamed ? d.difference().high() : -d.difference().low();
        String numbers = first + " " + number(asNamed ? d.meanA() : d.meanB()) + " against " + second + " "
                + number(asNamed ? d.meanB() : d.meanA()) + " (difference " + signed(sign * d.difference().estimate())
                + ", 95 % CI " + number(low) + " to " + number(high);
        String margin = "±" + VerdictText.plain(m.margin()) + unit(m);
        String tost = String.format(java.util.Locale.ROOT, "two one-sided t-tests p = %s, their 90 %% CI %s to %s",
                p(m.pTost()), number(asNamed ? m.tostLow() : -m.tostHigh()), number(asNamed ? m.tostHigh() : -m.tostLow()));
        String test = (VerdictText.directional(plan) ? "one-sided" : "paired") + " signed-rank p = " + p(d.p());
        return switch (m.finding()) {
            case HIGHER_A, HIGHER_B -> {
                String higher = m.finding() == Finding.HIGHER_A ? m.driverA() : m.driverB();
                yield "higher for " + higher + ": " + numbers + "; " + test + ")"
                        + (m.pTost() < AnalysisPlan.ALPHA ? ", yet inside the margin " + margin + " (" + tost + "): a"
                        + " difference too small to matter." : ".");
            }
            case EQUIVALENT -> "equivalent within " + margin + ": " + numbers + "; " + tost + (Double.isNaN(d.pAdjusted())
                    ? "; a difference not tested: " + tooFew(d) + ")." : "; no difference shown, " + test + ").");
            case INCONCLUSIVE -> "inconclusive: " + numbers + "). Neither a difference (" + test + ") nor equivalence"
                    + " within " + margin + " (" + tost + ") is shown" + VerdictText.detectable(d).replace("; it", "; the"
                    + " test") + ".";
            case TOO_FEW -> "no difference tested (" + m.note() + " for the signed-rank test to reach 5 %), and"
                    + " equivalence within " + margin + " is not shown (" + tost + "). " + numbers + ") describes the"
                    + " difference; it does not test it. Run more replications (--replications N).";
            case NOT_TESTABLE -> "not testable: " + m.note() + " (" + first + " " + number(asNamed ? d.meanA() : d.meanB())
                    + " against " + second + " " + number(asNamed ? d.meanB() : d.meanA()) + " on average), so this measure"
                    + " cannot tell the two drivers apart.";
        };
    }

    /** Why the difference was not tested: its smallest attainable p. */
    private static String tooFew(PairedDifference d) {
        return String.format(java.util.Locale.ROOT, "its smallest attainable p is %s", p(d.smallestP()));
    }

    /** "1 fault", "5 cells": the unit in the singular where the margin is one. */
    private static String unit(MeasureComparison m) {
        String unit = m.measure().unit();
        if (unit.isEmpty()) {
            return "";
        }
        return " " + (m.margin() == 1 && unit.endsWith("s") && !unit.contains(" ") ? unit.substring(0, unit.length() - 1)
                : unit);
    }
}
