package sitcov.report;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import sitcov.experiment.Comparison;
import sitcov.experiment.SituationFaults;

/**
 * The verdict of a comparison in a few plain sentences: for every pair of drivers, each measure
 * either differs (paired Wilcoxon p below {@link #ALPHA}) with its direction, size and uncertainty,
 * or is said not to; then the faults whose detection differs after Holm's correction; then what
 * the cells say about faults (the paper's uniformity hypothesis).
 */
final class VerdictText {
    static final double ALPHA = 0.05;
    /** Below this many replications the tests can hardly detect anything: say so. */
    static final int FEW_REPLICATIONS = 10;

    private VerdictText() {
    }

    static List<String> lines(Comparison comparison, List<SituationFaults.Uniformity> uniformity) {
        List<String> out = new ArrayList<>();
        List<Comparison.MeasureTest> all = comparison.measures();
        for (int i = 0; i < all.size(); i++) {
            Comparison.MeasureTest m = all.get(i);
            boolean firstOfPair = i == 0 || !samePair(all.get(i - 1), m);
            if (firstOfPair) {
                out.add(String.format(Locale.ROOT, "%s against %s over %d paired replications (differential oracle;"
                        + " difference = %s minus %s with its 95 %% bootstrap CI; p from the paired Wilcoxon signed-rank"
                        + " test):", m.driverA(), m.driverB(), m.replications(), m.driverA(), m.driverB()));
                if (m.replications() < FEW_REPLICATIONS) {
                    out.add("  (with fewer than " + FEW_REPLICATIONS + " replications these tests can hardly tell a"
                            + " real difference from chance: run more with --replications N)");
                }
            }
            out.add(measure(m));
            boolean lastOfPair = i == all.size() - 1 || !samePair(all.get(i + 1), m);
            if (lastOfPair) {
                out.add(faults(comparison, m.driverA(), m.driverB()));
            }
        }
        if (!uniformity.isEmpty()) {
            out.add(uniformity(uniformity));
        }
        return out;
    }

    private static boolean samePair(Comparison.MeasureTest x, Comparison.MeasureTest y) {
        return x.driverA().equals(y.driverA()) && x.driverB().equals(y.driverB());
    }

    private static String measure(Comparison.MeasureTest m) {
        String numbers = String.format(Locale.ROOT, "%s against %s (%s, CI %s to %s; p = %s; Â12 = %.2f, %s)",
                number(m.meanA()), number(m.meanB()), signed(m.difference().estimate()), number(m.difference().low()),
                number(m.difference().high()), p(m.pWilcoxon()), m.a12(), m.effect().label());
        if (m.pWilcoxon() < ALPHA && m.meanA() != m.meanB()) {
            String winner = m.meanA() > m.meanB() ? m.driverA() : m.driverB();
            return "- " + m.measure().words() + ": higher for " + winner + ", " + numbers + ".";
        }
        return "- " + m.measure().words() + ": no significant difference, " + numbers + ".";
    }

    /** The per-fault sentence of a pair: the faults whose detection differs after Holm's correction. */
    private static String faults(Comparison comparison, String a, String b) {
        List<String> differing = new ArrayList<>();
        int tested = 0;
        for (Comparison.FaultTest f : comparison.faults()) {
            if (!f.driverA().equals(a) || !f.driverB().equals(b)) {
                continue;
            }
            tested++;
            if (f.pHolm() < ALPHA) {
                double shareA = f.mapsA() == 0 ? 0 : 100.0 * f.foundA() / f.mapsA();
                double shareB = f.mapsB() == 0 ? 0 : 100.0 * f.foundB() / f.mapsB();
                differing.add(String.format(Locale.ROOT, "fault %d by %s (%.1f %% of its maps against %.1f %%, odds ratio"
                        + " %s, Holm p = %s)", f.fault().id(), shareA > shareB ? a : b, shareA, shareB,
                        number(f.oddsRatio()), p(f.pHolm())));
            }
        }
        String head = "- per fault, " + a + " against " + b + " (share of maps finding it; Fisher's exact test, Holm-adjusted"
                + " over " + tested + " faults): ";
        return head + (differing.isEmpty() ? "no fault is found on a significantly different share of maps."
                : "found on a larger share of maps: " + String.join("; ", differing) + "; no other fault differs.");
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
            return "- situations against faults: no fault was found on some maps and missed on others, so the cells"
                    + " cannot be tested as equivalence classes.";
        }
        return String.format(Locale.ROOT, "- situations against faults (the paper's uniformity hypothesis): the coverage"
                + " cell explains on average %.1f %% of the variation in whether a map finds a fault, against %.1f %% when"
                + " the same maps are dealt to cells at random; for %d of the %d faults found on some maps but not all,"
                + " more than chance (permutation p < %.2f).", 100 * explained / counted, 100 * chance / counted, beyond,
                counted, ALPHA);
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

    private static String signed(double v) {
        return (v > 0 ? "+" : "") + number(v);
    }

    static String p(double p) {
        return p < 0.001 ? String.format(Locale.ROOT, "%.1e", p) : String.format(Locale.ROOT, "%.3f", p);
    }
}
