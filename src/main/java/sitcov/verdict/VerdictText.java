package sitcov.verdict;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import sitcov.analysis.Comparison;
import sitcov.analysis.Finding;
import sitcov.analysis.MeasureComparison;
import sitcov.analysis.PairedDifference;
import sitcov.analysis.SituationFaults;
import sitcov.experiment.AnalysisPlan;
import sitcov.experiment.BudgetKind;
import sitcov.judge.Variant;
import sitcov.experiment.Direction;
import sitcov.experiment.Measure;

/**
 * The verdict of a comparison in plain sentences, claiming no more than the tests show: first the
 * answer to the preset's primary question, then once how to read the rest (the families, the words,
 * the caveats of few replications), then for each pair of drivers a one-line summary and each
 * measure's finding — higher, equivalent within the margin, inconclusive with what remains
 * possible, not tested or not testable — then the faults whose detection differs, then what the
 * cells say about faults (the paper's uniformity hypothesis). Lines starting "- " are items under
 * the line before them. {@link Reading} holds how to read it.
 */
public final class VerdictText {
    static final double ALPHA = AnalysisPlan.ALPHA;

    private VerdictText() {
    }

    public static List<String> lines(Comparison comparison, List<SituationFaults.Uniformity> uniformity, BudgetKind budget) {
        List<String> out = new ArrayList<>();
        if (comparison.replications() == 0) {
            out.add("No replications in this folder (a shard that got none), so nothing to compare: merge it with the"
                    + " other shards (merge SHARD... --out DIR) for the verdict.");
            return out;
        }
        Optional<MeasureComparison> primary = comparison.primary();
        if (primary.isPresent()) {
            out.add("Primary question (declared in the preset): " + question(comparison.plan(), budget));
            out.add("Answer: " + PrimaryAnswer.of(primary.get(), comparison.plan()));
        }
        List<MeasureComparison> all = comparison.measures();
        if (!all.isEmpty()) {
            // with one driver there is no pair to compare, and nothing for these paragraphs to explain
            Reading.fewReplications(comparison.replications()).ifPresent(out::add);
            Reading.unreachable(comparison).ifPresent(out::add);
            out.add(Reading.howToRead(comparison, budget));
        }
        int perPair = comparison.plan().measures().size();
        for (int i = 0; i < all.size(); i += perPair) {
            List<MeasureComparison> pair = all.subList(i, i + perPair);
            String a = pair.get(0).driverA();
            String b = pair.get(0).driverB();
            out.add(PairSummary.heading(a, b, comparison.replications()));
            out.add(PairSummary.inShort(pair, comparison.faults().stream()
                    .filter(f -> f.driverA().equals(a) && f.driverB().equals(b)).toList(), comparison.replications()));
            for (MeasureComparison m : pair) {
                out.add(measure(m));
            }
            out.add(FaultFindings.line(comparison, a, b));
        }
        if (!uniformity.isEmpty()) {
            out.add(PairSummary.HEADING + "Situations against faults (the paper's uniformity hypothesis)");
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

    static String measure(MeasureComparison m) {
        String words = m.measure().words();
        if (m.primary()) {
            return "- " + words + ": the primary question, answered above.";
        }
        PairedDifference d = m.paired();
        String numbers = numbers(d);
        String a12 = ahead(m);
        return switch (m.finding()) {
            case HIGHER_A, HIGHER_B -> "- " + words + ": higher for " + (m.finding() == Finding.HIGHER_A ? m.driverA()
                    : m.driverB()) + ", " + numbers + "; Holm p = " + p(d.pAdjusted()) + "; " + a12 + ")"
                    + (m.pTostAdjusted() < ALPHA ? ", by less than the margin ±" + plain(m.margin()) + " (equivalent"
                    + " too, Holm p = " + p(m.pTostAdjusted()) + "): too small to matter." : ".");
            case EQUIVALENT -> "- " + words + ": equivalent within ±" + plain(m.margin()) + ", " + numbers
                    + "; two one-sided tests Holm p = " + p(m.pTostAdjusted()) + "; " + a12 + ").";
            case INCONCLUSIVE -> "- " + words + ": inconclusive, " + numbers + "; difference Holm p = " + p(d.pAdjusted())
                    + (Double.isNaN(m.pTostAdjusted()) ? "" : ", within ±" + plain(m.margin()) + " Holm p = "
                    + p(m.pTostAdjusted())) + "; " + a12 + ")" + detectable(d) + ".";
            case TOO_FEW -> "- " + words + ": not tested (" + m.note() + "), " + numbers + "; " + a12 + ")"
                    + (Double.isNaN(m.pTostAdjusted()) ? "" : "; not shown equivalent within ±" + plain(m.margin())
                    + " (Holm p = " + p(m.pTostAdjusted()) + ")") + ".";
            case NOT_TESTABLE -> "- " + words + ": not testable: " + m.note() + ".";
        };
    }

    /**
     * The paired effect size in words: "coverage-filter higher in 27 of 30 replications, random in 2" (ties
     * are the rest), the replications compared each with its own pair.
     */
    static String ahead(MeasureComparison m) {
        PairedDifference d = m.paired();
        boolean a = d.higherA() >= d.higherB();
        return (a ? m.driverA() : m.driverB()) + " higher in " + (a ? d.higherA() : d.higherB()) + " of "
                + d.replications() + " replications, " + (a ? m.driverB() : m.driverA()) + " in "
                + (a ? d.higherB() : d.higherA());
    }

    /** "13.60 against 13.67 (−0.067, CI −0.700 to 0.534", left open for the test that follows. */
    static String numbers(PairedDifference d) {
        return number(d.meanA()) + " against " + number(d.meanB()) + " (" + signed(d.difference().estimate()) + ", CI "
                + number(d.difference().low()) + " to " + number(d.difference().high());
    }

    static String detectable(PairedDifference d) {
        return !Double.isFinite(d.detectable()) ? "" : "; it could have detected a difference of " + number(d.detectable())
                + " or more";
    }

    /** Faults found (or missed) on fewer distinct maps than this are too rare for the uniformity test to say anything. */
    public static final int UNIFORMITY_MIN_MAPS = 5;

    static final String TOO_RARE = "found on fewer than " + UNIFORMITY_MIN_MAPS + " maps";
    static final String TOO_RARELY_MISSED = "missed on fewer than " + UNIFORMITY_MIN_MAPS + " maps";

    /** Why a fault found on {@code found} of {@code maps} distinct maps is left out of the uniformity average, if it is. */
    public static Optional<String> leftOut(int found, int maps) {
        if (found == 0) {
            return Optional.of("never found");
        }
        if (found == maps) {
            return Optional.of("found on every map");
        }
        if (found < UNIFORMITY_MIN_MAPS) {
            return Optional.of(TOO_RARE);
        }
        return maps - found < UNIFORMITY_MIN_MAPS ? Optional.of(TOO_RARELY_MISSED) : Optional.empty();
    }

    static String uniformity(List<SituationFaults.Uniformity> tests) {
        double explained = 0;
        double chance = 0;
        List<Variant> counted = new ArrayList<>();
        List<Variant> rare = new ArrayList<>();
        List<Variant> common = new ArrayList<>();
        int beyond = 0;
        for (SituationFaults.Uniformity u : tests) {
            Optional<String> out = leftOut(u.found(), u.maps());
            if (out.isPresent()) {
                if (out.get().equals(TOO_RARE)) {
                    rare.add(u.variant());
                } else if (out.get().equals(TOO_RARELY_MISSED)) {
                    common.add(u.variant());
                }
                continue;
            }
            counted.add(u.variant());
            explained += u.explained();
            chance += u.byChance();
            beyond += u.p() < ALPHA ? 1 : 0;
        }
        int maps = tests.get(0).maps();
        List<String> left = new ArrayList<>();
        if (!rare.isEmpty()) {
            left.add(ids(rare) + " (" + TOO_RARE + ")");
        }
        if (!common.isEmpty()) {
            left.add(ids(common) + " (" + TOO_RARELY_MISSED + ")");
        }
        String leftOut = left.isEmpty() ? "" : " Left out as too rare to test: " + String.join(", ", left) + ".";
        if (counted.isEmpty()) {
            return String.format(Locale.ROOT, "Over the %d distinct maps run (a map run by several drivers counted once),"
                    + " no fault was found on %d or more maps and missed on %d or more, so the cells cannot be tested as"
                    + " equivalence classes.", maps, UNIFORMITY_MIN_MAPS, UNIFORMITY_MIN_MAPS) + leftOut;
        }
        return String.format(Locale.ROOT, "Over the %d distinct maps run (a map run by several drivers counted once), for"
                + " the %s found on some maps but not all (%s), the coverage cell explains on average %.1f %% of"
                + " the variation in whether a map finds the fault, against %.1f %% when the same maps are dealt to cells"
                + " at random; for %d of them more than chance (permutation p < %s, not adjusted).", maps,
                counted.size() == 1 ? noun(counted, 1) : counted.size() + " " + noun(counted, counted.size()),
                ids(counted), 100 * explained / counted.size(), 100 * chance / counted.size(), beyond, plain(ALPHA))
                + leftOut;
    }

    /** "fault 16", "faults 2, 8": seeded faults by their word, other controllers as "variant 1", "variants 1, 2". */
    static String ids(List<Variant> ids) {
        return noun(ids, ids.size()) + " " + String.join(", ", ids.stream().map(v -> String.valueOf(v.id())).toList());
    }

    /** "fault", "faults", "variant" or "variants": a variant is a fault where the builtin car's seeded faults are meant. */
    static String noun(List<Variant> of, int count) {
        String word = of.stream().allMatch(v -> v instanceof Variant.Seeded) ? "fault" : "variant";
        return count == 1 ? word : word + "s";
    }

    public static String number(double v) {
        if (Double.isNaN(v)) {
            return "n/a";
        }
        if (Double.isInfinite(v)) {
            return v > 0 ? "inf" : "-inf";
        }
        double a = Math.abs(v);
        return String.format(Locale.ROOT, a >= 100 ? "%.1f" : a >= 1 ? "%.2f" : "%.3f", v);
    }

    public static String plain(double v) {
        return Comparison.plain(v);
    }

    public static String signed(double v) {
        return (v > 0 ? "+" : "") + number(v);
    }

    public static String p(double p) {
        if (Double.isNaN(p)) {
            return "n/a";
        }
        return p == 0 ? "0" : p < 0.001 ? String.format(Locale.ROOT, "%.1e", p) : String.format(Locale.ROOT, "%.3f", p);
    }

    static boolean directional(AnalysisPlan plan) {
        return plan.primaryDirection() != Direction.TWO_SIDED;
    }
}
