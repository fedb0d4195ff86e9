package sitcov.verdict;

import static sitcov.verdict.VerdictText.ids;
import static sitcov.verdict.VerdictText.p;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;
import sitcov.analysis.Comparison;
import sitcov.analysis.FaultComparison;
import sitcov.analysis.Finding;
import sitcov.analysis.PairedDifference;
import sitcov.judge.Variant;

/**
 * The per-fault sentence of one pair, a screening: which faults each driver's maps find more often (flagged
 * under Benjamini–Hochberg), where no difference was shown and what the test could have detected, and which
 * faults no difference could have flagged or were not tested.
 */
public final class FaultFindings {
    private FaultFindings() {
    }

    static String line(Comparison comparison, String a, String b) {
        List<String> moreA = new ArrayList<>();
        List<String> moreB = new ArrayList<>();
        List<Variant> none = new ArrayList<>();
        List<Variant> unreachable = new ArrayList<>();
        double lowest = Double.POSITIVE_INFINITY;
        double highest = 0;
        Map<String, List<Variant>> untested = new TreeMap<>();
        for (FaultComparison f : comparison.faults()) {
            if (!f.driverA().equals(a) || !f.driverB().equals(b)) {
                continue;
            }
            Variant id = f.variant();
            switch (f.finding()) {
                case HIGHER_A -> moreA.add(found(f));
                case HIGHER_B -> moreB.add(found(f));
                case INCONCLUSIVE -> {
                    (Double.isFinite(f.paired().detectable()) ? none : unreachable).add(id);
                    if (Double.isFinite(f.paired().detectable())) {
                        lowest = Math.min(lowest, f.paired().detectable());
                        highest = Math.max(highest, f.paired().detectable());
                    }
                }
                case TOO_FEW -> untested.computeIfAbsent(Comparison.tooFewReplications(f.paired().replications())
                        ? "too few replications" : "too few replications differ", k -> new ArrayList<>()).add(id);
                case NOT_TESTABLE -> untested.computeIfAbsent(f.note(), k -> new ArrayList<>()).add(id);
                case EQUIVALENT -> throw new IllegalStateException("faults are not tested for equivalence");
            }
        }
        String word = VerdictText.noun(comparison.faults().stream().map(FaultComparison::variant).toList(), 1);
        StringBuilder s = new StringBuilder("- per " + word + ", a screening (each replication's share of its maps finding"
                + " the " + word + ", paired signed-rank test; Benjamini-Hochberg over every pair's " + word + "s): ");
        List<String> parts = new ArrayList<>();
        if (!moreA.isEmpty()) {
            parts.add("found on a larger share of " + a + "'s maps: " + String.join("; ", moreA));
        }
        if (!moreB.isEmpty()) {
            parts.add("found on a larger share of " + b + "'s maps: " + String.join("; ", moreB));
        }
        if (!none.isEmpty()) {
            String range = points(lowest).equals(points(highest)) ? points(lowest) : points(lowest) + " to " + points(highest);
            parts.add("no difference shown for " + ids(none) + (lowest <= highest ? " (the test could have detected " + range
                    + " points or more)" : ""));
        }
        if (!unreachable.isEmpty()) {
            parts.add(ids(unreachable) + " could not have been flagged, however large the difference (too few of the"
                    + " replications differ for the level the screening needed)");
        }
        List<String> why = new ArrayList<>();
        untested.forEach((reason, ids) -> why.add(ids(ids) + " (" + reason + ")"));
        if (!why.isEmpty()) {
            parts.add("not tested: " + String.join(", ", why));
        }
        return s.append(parts.isEmpty() ? "no " + word + "s." : String.join("; ", parts) + ".").toString();
    }

    /** "fault 16 (59.8 % of fault-search's maps against 38.7 % of random's, +21.3 points, CI …)": the higher first. */
    private static String found(FaultComparison f) {
        PairedDifference d = f.paired();
        boolean a = f.finding() == Finding.HIGHER_A;
        double sign = a ? 1 : -1;
        double low = a ? d.difference().low() : -d.difference().high();
        double high = a ? d.difference().high() : -d.difference().low();
        return String.format(Locale.ROOT, "%s %d (%s %% of %s's maps against %s %% of %s's, +%s points, CI %s to %s;"
                + " BH q = %s)", VerdictText.noun(List.of(f.variant()), 1), f.variant().id(), percent(a ? d.meanA() : d.meanB()), a ? f.driverA() : f.driverB(),
                percent(a ? d.meanB() : d.meanA()), a ? f.driverB() : f.driverA(), points(sign * d.difference().estimate()),
                points(low), points(high), p(d.pAdjusted()));
    }

    private static String percent(double share) {
        return String.format(Locale.ROOT, "%.1f", 100 * share);
    }

    /** A difference of shares in percentage points. */
    private static String points(double share) {
        return String.format(Locale.ROOT, "%.1f", 100 * share);
    }

    public static boolean differs(Finding f) {
        return f == Finding.HIGHER_A || f == Finding.HIGHER_B;
    }
}
