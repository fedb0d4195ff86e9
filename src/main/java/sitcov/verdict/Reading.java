package sitcov.verdict;

import static sitcov.verdict.VerdictText.plain;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import sitcov.analysis.Comparison;
import sitcov.analysis.Families;
import sitcov.analysis.Finding;
import sitcov.experiment.AnalysisPlan;
import sitcov.experiment.BudgetKind;

/** The verdict's paragraphs on how to read it: the analysis plan in words, and the caveats of few replications. */
final class Reading {
    /** Up to this many replications a 95 % percentile bootstrap CI is too narrow to be read as one. */
    static final int DESCRIBING_CIS = 10;

    private Reading() {
    }

    /**
     * The caveat of few replications, said once: with 5 or fewer no signed-rank test can reach the
     * level, so nothing is tested for a difference; with 10 or fewer the CIs only describe (a percentile
     * bootstrap of so few values covers the mean difference less often than it says).
     */
    static Optional<String> fewReplications(int n) {
        if (Comparison.tooFewReplications(n)) {
            double smallest = Math.min(1, 2 / Math.pow(2, Math.max(0, n)));
            return Optional.of(String.format(Locale.ROOT, "Nothing below is tested for a difference: with %d paired"
                    + " replications no signed-rank test can reach p < %s (its smallest two-sided p is 2/2^%d = %s), so the"
                    + " differences, their CIs and the counts of replications describe the differences, they do not test"
                    + " them. Run at least 6 with --replications N (30 is the usual minimum).", n, plain(AnalysisPlan.ALPHA),
                    n, plain(smallest)));
        }
        if (n <= DESCRIBING_CIS) {
            return Optional.of(String.format(Locale.ROOT, "With %d paired replications the 95 %% CIs only describe: a"
                    + " percentile bootstrap of %d or fewer values is too narrow to hold the true difference 95 %% of the"
                    + " time, so what is shown rests on the tests alone. 30 replications is the usual minimum.", n,
                    DESCRIBING_CIS));
        }
        return Optional.empty();
    }

    /**
     * The caveat of tests that no difference could have passed at this n (the smallest p of their
     * signed-rank test is above the level their family holds them to), said once for all of them.
     */
    static Optional<String> unreachable(Comparison c) {
        long measures = c.measures().stream().filter(m -> !m.primary() && m.finding() == Finding.INCONCLUSIVE
                && Double.isInfinite(m.paired().detectable())).count();
        long faults = c.faults().stream().filter(f -> f.finding() == Finding.INCONCLUSIVE
                && Double.isInfinite(f.paired().detectable())).count();
        if (measures + faults == 0 || Comparison.tooFewReplications(c.replications())) {
            return Optional.empty();
        }
        return Optional.of(String.format(Locale.ROOT, "%d of the exploratory tests below (%d of measures, %d per fault)"
                + " could not have shown a difference, however large: so few of their replications differ that the"
                + " smallest p their signed-rank test can give is above the level their family holds them to, and their"
                + " \"inconclusive\" says only that. More replications would tell more (--replications N).",
                measures + faults, measures, faults));
    }

    static String howToRead(Comparison c, BudgetKind budget) {
        Families f = c.families();
        StringBuilder s = new StringBuilder("How to read this verdict: ").append(c.replications()).append(" paired"
                + " replications (the replication is the unit: the drivers of one read the same candidates)");
        s.append(budget == BudgetKind.TICKS ? "; each pair is compared on the maps each driver had judged within the ticks"
                + " both spent." : "; each driver's measures are over everything it ran in the same wall-clock time.");
        s.append(c.primary().isPresent() ? " The primary question is tested at 5 % on its own. The other tests are"
                : " The tests are").append(" exploratory, in two families. Measures");
        List<String> kinds = new ArrayList<>();
        kind(kinds, f.differences(), "difference");
        kind(kinds, f.equivalences(), "equivalence");
        s.append(f.places() == 0 ? " (none tested)" : " (" + f.places() + " of pairs, " + String.join(" and ", kinds)
                + " tests)").append(": a measure's difference and equivalence tests are tested together by closed testing"
                + " (they cannot both be false), Holm's method over the measures, so the chance of any false claim among"
                + " them stays at 5 %; \"Holm p\" below is so adjusted. Faults (").append(f.faults()).append(f.faults() == 1
                ? " test" : " tests").append("): a screening family under Benjamini-Hochberg, so that of the faults it"
                + " flags at most 5 % are expected to be false discoveries (\"BH q\" below); a flag says where to look, not"
                + " a claim held to the measures' standard.");
        s.append(" \"Higher\": a difference shown by the paired signed-rank test. \"Equivalent within ±m\": two one-sided"
                + " t-tests show the mean difference inside the preset's margin ±m. \"Inconclusive\": neither shown; the"
                + " 95 % bootstrap CI says what is still possible, and \"could have detected d\" is the difference the test"
                + " would have found with 80 % probability. \"Not tested\": too few replications differ for the test to"
                + " reach 5 %. \"Higher in k of n replications\" is the paired effect size: in how many paired"
                + " replications each driver was ahead.");
        return s.toString();
    }

    private static void kind(List<String> kinds, int count, String what) {
        if (count > 0) {
            kinds.add(count + " " + what);
        }
    }
}
