package sitcov.verdict;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import sitcov.analysis.Comparison;
import sitcov.analysis.FaultComparison;
import sitcov.analysis.Finding;
import sitcov.analysis.MeasureComparison;
import sitcov.analysis.PairedDifference;

/**
 * The top of one pair's part of a verdict: a heading naming the pair, then its bottom line in one
 * sentence — who is ahead on what, what is shown equivalent, what shows no difference and what was
 * not tested — so a reader of several pairs can stop after the first line of each. Where no
 * difference could be tested at all, the line says so and describes the largest differences with
 * their CIs instead: "no difference shown" beside 168.8 cells against 82.2 would read as a finding.
 */
public final class PairSummary {
    /** Marks a heading line of the verdict (a Markdown heading; the HTML report draws it as one). */
    public static final String HEADING = "## ";
    /** Starts a pair's bottom line. */
    public static final String IN_SHORT = "In short: ";
    /** How many of the largest differences an untested pair's line describes. */
    static final int LARGEST = 3;

    private PairSummary() {
    }

    static String heading(String a, String b, int replications) {
        return HEADING + a + " against " + b + " (" + replications + " paired replications)";
    }

    /** "In short: A is ahead on …; B on …; equivalent in …; the other 2 measures show no difference; 1 not tested." */
    static String inShort(List<MeasureComparison> pair, List<FaultComparison> faults, int replications) {
        String a = pair.get(0).driverA();
        String b = pair.get(0).driverB();
        List<String> aheadA = new ArrayList<>();
        List<String> aheadB = new ArrayList<>();
        List<String> equivalent = new ArrayList<>();
        int inconclusive = 0;
        int untested = 0;
        int untestable = 0;
        for (MeasureComparison m : pair) {
            String name = name(m) + (m.primary() ? " (the primary question)" : "");
            switch (m.finding()) {
                case HIGHER_A -> aheadA.add(name);
                case HIGHER_B -> aheadB.add(name);
                case EQUIVALENT -> equivalent.add(name);
                case INCONCLUSIVE -> inconclusive++;
                case TOO_FEW -> untested++;
                case NOT_TESTABLE -> untestable++;
            }
        }
        if (!differenceTested(pair, faults)) {
            return untested(pair, equivalent, replications);
        }
        faults(faults, Finding.HIGHER_A).ifPresent(aheadA::add);
        faults(faults, Finding.HIGHER_B).ifPresent(aheadB::add);
        List<String> parts = new ArrayList<>();
        boolean ahead = !aheadA.isEmpty() || !aheadB.isEmpty();
        if (!aheadA.isEmpty()) {
            parts.add(a + " is ahead on " + and(aheadA));
        }
        if (!aheadB.isEmpty()) {
            parts.add((aheadA.isEmpty() ? b + " is ahead on " : b + " on ") + and(aheadB));
        }
        if (!ahead && inconclusive > 0) {
            parts.add("no difference shown between " + a + " and " + b + (inconclusive == pair.size() ? ""
                    : " in " + count(inconclusive)));
        }
        if (!equivalent.isEmpty()) {
            parts.add("equivalent in " + and(equivalent));
        }
        if (ahead && inconclusive > 0) {
            parts.add("the other " + (inconclusive == 1 ? "measure tested shows" : inconclusive + " measures tested show")
                    + " no difference");
        }
        if (untested > 0) {
            parts.add(count(untested) + " not tested (too few replications differ)");
        }
        if (untestable > 0) {
            parts.add(count(untestable) + " not testable");
        }
        return IN_SHORT + String.join("; ", parts) + ".";
    }

    /** Whether any difference test of the pair, of a measure or a fault, could reach the level. */
    static boolean differenceTested(List<MeasureComparison> pair, List<FaultComparison> faults) {
        return pair.stream().anyMatch(m -> !Double.isNaN(m.paired().pAdjusted()))
                || faults.stream().anyMatch(f -> !Double.isNaN(f.paired().pAdjusted()));
    }

    /**
     * "In short: no difference tested (…); the largest differences, described: cells covered 168.8 against
     * 82.2 (+86.6, CI 83.0 to 90.0); …": the measures whose CI leaves out 0, largest against their spread first.
     */
    private static String untested(List<MeasureComparison> pair, List<String> equivalent, int replications) {
        String why = Comparison.tooFewReplications(replications) ? "with " + replications + " paired replications no"
                + " signed-rank test can reach 5 %" : "too few replications differ for any test to reach 5 %";
        List<MeasureComparison> largest = pair.stream().filter(m -> m.note() == null || m.finding() == Finding.TOO_FEW)
                .filter(m -> excludesZero(m.paired()))
                .sorted(Comparator.comparingDouble((MeasureComparison m) -> standardised(m.paired())).reversed())
                .limit(LARGEST).toList();
        String described = largest.isEmpty() ? "no difference stands out: every CI holds 0"
                : "the largest differences, described: " + String.join("; ", largest.stream()
                        .map(m -> name(m) + " " + VerdictText.numbers(m.paired()) + ")").toList());
        return IN_SHORT + "no difference tested (" + why + ")" + (equivalent.isEmpty() ? ""
                : "; equivalent in " + and(equivalent)) + "; " + described + ".";
    }

    private static boolean excludesZero(PairedDifference d) {
        return d.difference().low() > 0 || d.difference().high() < 0;
    }

    /** |mean difference| over the spread of the differences: infinite where every replication differs alike. */
    private static double standardised(PairedDifference d) {
        double size = Math.abs(d.difference().estimate());
        return d.spread() > 0 ? size / d.spread() : Double.POSITIVE_INFINITY;
    }

    private static String count(int measures) {
        return measures == 1 ? "1 measure" : measures + " measures";
    }

    /** "3 faults (0, 7, 16)" found on a larger share of one driver's maps, if any. */
    private static java.util.Optional<String> faults(List<FaultComparison> faults, Finding finding) {
        List<sitcov.judge.Variant> found = faults.stream().filter(f -> f.finding() == finding).map(FaultComparison::variant)
                .toList();
        if (found.isEmpty()) {
            return java.util.Optional.empty();
        }
        return java.util.Optional.of(found.size() == 1 ? VerdictText.ids(found) + " (found on more of its maps, screening)"
                : found.size() + " " + VerdictText.noun(found, found.size()) + " found on more of its maps (screening: "
                + String.join(", ", found.stream().map(v -> String.valueOf(v.id())).toList()) + ")");
    }

    private static String and(List<String> items) {
        if (items.size() == 1) {
            return items.get(0);
        }
        return String.join(", ", items.subList(0, items.size() - 1)) + " and " + items.get(items.size() - 1);
    }

    /** The measure's words without the paper's name in brackets: a summary line is short. */
    private static String name(MeasureComparison m) {
        return m.measure().words().replaceFirst(" \\(.*\\)$", "");
    }
}
