package sitcov.report;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import sitcov.experiment.AnalysisPlan;
import sitcov.experiment.BudgetKind;
import sitcov.experiment.Comparison;
import sitcov.experiment.Direction;
import sitcov.experiment.Finding;
import sitcov.experiment.MeasureTest;
import sitcov.experiment.PairedDifference;
import sitcov.experiment.SituationFaults;

/**
 * The verdict of a comparison in plain sentences, claiming no more than the tests show: first the
 * answer to the preset's primary question, then once how to read the rest (the family, the words,
 * the caveat of few replications), then for each pair of drivers a one-line summary and each
 * measure's finding — higher, equivalent within the margin, inconclusive with what remains
 * possible, not tested or not testable — then the faults whose detection differs, then what the
 * cells say about faults (the paper's uniformity hypothesis). Lines starting "- " are items under
 * the line before them.
 */
final class VerdictText {
    static final double ALPHA = AnalysisPlan.ALPHA;

    private VerdictText() {
    }

    static List<String> lines(Comparison comparison, List<SituationFaults.Uniformity> uniformity, BudgetKind budget) {
        List<String> out = new ArrayList<>();
        Optional<MeasureTest> primary = comparison.primary();
        if (primary.isPresent()) {
            out.add("Primary question (declared in the preset): " + question(comparison.plan(), budget));
            out.add("Answer: " + PrimaryAnswer.of(primary.get(), comparison.plan()));
        }
        fewReplications(comparison.replications()).ifPresent(out::add);
        out.add(howToRead(comparison, budget));
        List<MeasureTest> all = comparison.measures();
        for (int i = 0; i < all.size(); i += sitcov.experiment.Measure.values().length) {
            List<MeasureTest> pair = all.subList(i, i + sitcov.experiment.Measure.values().length);
            out.add(PairSummary.heading(pair, comparison.replications()));
            for (MeasureTest m : pair) {
                out.add(measure(m));
            }
            out.add(FaultFindings.line(comparison, pair.get(0).driverA(), pair.get(0).driverB()));
        }
        if (!uniformity.isEmpty()) {
            out.add(uniformity(uniformity));
        }
        return out;
    }

    private static String question(AnalysisPlan plan, BudgetKind budget) {
        String first = plan.primaryDrivers().get(0);
        String second = plan.primaryDrivers().get(1);
        String words = plan.primaryMeasure().words();
        String compute = budget == BudgetKind.TICKS ? "for the same simulated ticks" : "for the same wall-clock time";
        return switch (plan.primaryDirection()) {
            case TWO_SIDED -> "do " + first + " and " + second + " differ in " + words + " " + compute + "?";
            case HIGHER -> "is " + words + " higher for " + first + " than for " + second + " " + compute + "?";
            case LOWER -> "is " + words + " lower for " + first + " than for " + second + " " + compute + "?";
        };
    }

    /** The caveat of too few replications for any signed-rank test, said once; empty when there is none. */
    static Optional<String> fewReplications(int n) {
        if (!Comparison.tooFewReplications(n)) {
            return Optional.empty();
        }
        double smallest = Math.min(1, 2 / Math.pow(2, Math.max(0, n)));
        return Optional.of(String.format(Locale.ROOT, "Too few replications to test: with %d paired replications no"
                + " signed-rank test can reach p < %s (its smallest two-sided p is 2/2^%d = %s), so the CIs and Â12 below"
                + " describe the differences, they do not test them. Run at least 6 with --replications N (30 is the"
                + " usual minimum).", n, plain(ALPHA), n, plain(smallest)));
    }

    private static String howToRead(Comparison c, BudgetKind budget) {
        StringBuilder s = new StringBuilder("How to read this verdict: ").append(c.replications()).append(" paired"
                + " replications (the replication is the unit: the drivers of one read the same candidates)");
        s.append(budget == BudgetKind.TICKS ? "; each pair is compared on the maps each driver had judged within the ticks"
                + " both spent." : "; each driver's measures are over everything it ran in the same wall-clock time.");
        List<String> kinds = new ArrayList<>();
        kind(kinds, c.familyMeasureDifferences(), "difference", "of measures");
        kind(kinds, c.familyEquivalences(), "equivalence", "of measures");
        kind(kinds, c.familyFaults(), "per-fault difference", "");
        s.append(c.primary().isPresent() ? " The primary question is tested at 5 % on its own; the other " : " The ")
                .append(c.familySize()).append(" tests").append(kinds.isEmpty() ? "" : " (" + String.join(", ", kinds) + ")")
                .append(" are exploratory, held together to a 5 % family-wise error by Holm's method: the p-values below"
                        + " are Holm-adjusted.");
        s.append(" \"Higher\": a difference shown by the paired signed-rank test. \"Equivalent within ±m\": two one-sided"
                + " t-tests show the mean difference inside the preset's margin ±m. \"Inconclusive\": neither shown; the"
                + " 95 % bootstrap CI says what is still possible, and \"could have detected d\" is the difference the test"
                + " would have found with 80 % probability. \"Not tested\": too few replications differ for the test to"
                + " reach 5 %. Â12 (Vargha-Delaney) compares the replications unpaired and only describes.");
        return s.toString();
    }

    private static void kind(List<String> kinds, int count, String what, String of) {
        if (count > 0) {
            kinds.add(count + " " + what + (count == 1 ? "" : "s") + (of.isEmpty() ? "" : " " + of));
        }
    }

    static String measure(MeasureTest m) {
        String words = m.measure().words();
        if (m.primary()) {
            return "- " + words + ": the primary question, answered above.";
        }
        PairedDifference d = m.paired();
        String numbers = numbers(d);
        String a12 = String.format(Locale.ROOT, "Â12 %.2f, %s", m.a12(), m.effect().label());
        return switch (m.finding()) {
            case HIGHER_A, HIGHER_B -> "- " + words + ": higher for " + (m.finding() == Finding.HIGHER_A ? m.driverA()
                    : m.driverB()) + ", " + numbers + "; Holm p = " + p(d.pAdjusted()) + "; " + a12 + ")"
                    + (m.pTostAdjusted() < ALPHA ? ", by less than the margin ±" + plain(m.margin()) + " (equivalent"
                    + " too, Holm p = " + p(m.pTostAdjusted()) + "): too small to matter." : ".");
            case EQUIVALENT -> "- " + words + ": equivalent within ±" + plain(m.margin()) + ", " + numbers
                    + "; two one-sided tests Holm p = " + p(m.pTostAdjusted()) + ").";
            case INCONCLUSIVE -> "- " + words + ": inconclusive, " + numbers + "; difference Holm p = " + p(d.pAdjusted())
                    + (Double.isNaN(m.pTostAdjusted()) ? "" : ", within ±" + plain(m.margin()) + " Holm p = "
                    + p(m.pTostAdjusted())) + ")" + detectable(d) + ".";
            case TOO_FEW -> "- " + words + ": not tested (" + m.note() + "), " + numbers + "; " + a12 + ")"
                    + (Double.isNaN(m.pTostAdjusted()) ? "" : "; not shown equivalent within ±" + plain(m.margin())
                    + " (Holm p = " + p(m.pTostAdjusted()) + ")") + ".";
            case NOT_TESTABLE -> "- " + words + ": not testable: " + m.note() + ".";
        };
    }

    /** "13.60 against 13.67 (−0.067, CI −0.700 to 0.534", left open for the test that follows. */
    static String numbers(PairedDifference d) {
        return number(d.meanA()) + " against " + number(d.meanB()) + " (" + signed(d.difference().estimate()) + ", CI "
                + number(d.difference().low()) + " to " + number(d.difference().high());
    }

    static String detectable(PairedDifference d) {
        if (Double.isInfinite(d.detectable())) {
            return "; at this n no difference could have reached the level the test was held to";
        }
        return Double.isNaN(d.detectable()) ? "" : "; it could have detected a difference of " + number(d.detectable())
                + " or more";
    }

    private static String uniformity(List<SituationFaults.Uniformity> tests) {
        double explained = 0;
        double chance = 0;
        int counted = 0;
        int beyond = 0;
        for (SituationFaults.Uniformity u : tests) {
            if (u.found() == 0 || u.found() == u.maps()) {
                continue;
            }
            counted++;
            explained += u.explained();
            chance += u.byChance();
            beyond += u.p() < ALPHA ? 1 : 0;
        }
        if (counted == 0) {
            return "Situations against faults: no fault was found on some maps and missed on others, so the cells"
                    + " cannot be tested as equivalence classes.";
        }
        return String.format(Locale.ROOT, "Situations against faults (the paper's uniformity hypothesis): the coverage"
                + " cell explains on average %.1f %% of the variation in whether a map finds a fault, against %.1f %% when"
                + " the same maps are dealt to cells at random; for %d of the %d faults found on some maps but not all,"
                + " more than chance (permutation p < %.2f, not adjusted).", 100 * explained / counted,
                100 * chance / counted, beyond, counted, ALPHA);
    }

    static String number(double v) {
        if (Double.isNaN(v)) {
            return "n/a";
        }
        if (Double.isInfinite(v)) {
            return v > 0 ? "inf" : "-inf";
        }
        double a = Math.abs(v);
        return String.format(Locale.ROOT, a >= 100 ? "%.1f" : a >= 1 ? "%.2f" : "%.3f", v);
    }

    static String plain(double v) {
        return Comparison.plain(v);
    }

    static String signed(double v) {
        return (v > 0 ? "+" : "") + number(v);
    }

    static String p(double p) {
        if (Double.isNaN(p)) {
            return "n/a";
        }
        return p == 0 ? "0" : p < 0.001 ? String.format(Locale.ROOT, "%.1e", p) : String.format(Locale.ROOT, "%.3f", p);
    }

    static boolean directional(AnalysisPlan plan) {
        return plan.primaryDirection() != Direction.TWO_SIDED;
    }
}
