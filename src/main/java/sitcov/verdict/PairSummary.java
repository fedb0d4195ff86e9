package sitcov.verdict;

import java.util.ArrayList;
import java.util.List;
import sitcov.analysis.FaultComparison;
import sitcov.analysis.Finding;
import sitcov.analysis.MeasureComparison;

/**
 * The top of one pair's part of a verdict: a heading naming the pair, then its bottom line in one
 * sentence — who is ahead on what, what is shown equivalent, how much shows nothing — so a reader
 * of several pairs can stop after the first line of each.
 */
public final class PairSummary {
    /** Marks a heading line of the verdict (a Markdown heading; the HTML report draws it as one). */
    public static final String HEADING = "## ";
    /** Starts a pair's bottom line. */
    public static final String IN_SHORT = "In short: ";

    private PairSummary() {
    }

    static String heading(String a, String b, int replications) {
        return HEADING + a + " against " + b + " (" + replications + " paired replications)";
    }

    /** "In short: A is ahead on …; B on …; equivalent in …; the other 2 measures show no difference." */
    static String inShort(List<MeasureComparison> pair, List<FaultComparison> faults) {
        String a = pair.get(0).driverA();
        String b = pair.get(0).driverB();
        List<String> aheadA = new ArrayList<>();
        List<String> aheadB = new ArrayList<>();
        List<String> equivalent = new ArrayList<>();
        int nothing = 0;
        for (MeasureComparison m : pair) {
            String name = name(m) + (m.primary() ? " (the primary question)" : "");
            switch (m.finding()) {
                case HIGHER_A -> aheadA.add(name);
                case HIGHER_B -> aheadB.add(name);
                case EQUIVALENT -> equivalent.add(name);
                default -> nothing++;
            }
        }
        faults(faults, Finding.HIGHER_A).ifPresent(aheadA::add);
        faults(faults, Finding.HIGHER_B).ifPresent(aheadB::add);
        List<String> parts = new ArrayList<>();
        if (!aheadA.isEmpty()) {
            parts.add(a + " is ahead on " + and(aheadA));
        }
        if (!aheadB.isEmpty()) {
            parts.add((aheadA.isEmpty() ? b + " is ahead on " : b + " on ") + and(aheadB));
        }
        if (aheadA.isEmpty() && aheadB.isEmpty()) {
            parts.add("no difference shown between " + a + " and " + b);
        }
        if (!equivalent.isEmpty()) {
            parts.add("equivalent in " + and(equivalent));
        }
        if (nothing > 0 && !(aheadA.isEmpty() && aheadB.isEmpty())) {
            parts.add("the other " + (nothing == 1 ? "measure shows" : nothing + " measures show") + " no difference");
        }
        return IN_SHORT + String.join("; ", parts) + ".";
    }

    /** "3 faults (0, 7, 16)" found on a larger share of one driver's maps, if any. */
    private static java.util.Optional<String> faults(List<FaultComparison> faults, Finding finding) {
        List<sitcov.judge.Variant> found = faults.stream().filter(f -> f.finding() == finding).map(FaultComparison::variant)
                .toList();
        if (found.isEmpty()) {
            return java.util.Optional.empty();
        }
        return java.util.Optional.of(found.size() == 1 ? VerdictText.ids(found) + " (found on more of its maps)"
                : found.size() + " " + VerdictText.noun(found, found.size()) + " found on more of its maps ("
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
