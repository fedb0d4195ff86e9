package sitcov.verdict;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import sitcov.analysis.OwnFailures;

/** The verdict's paragraph on the reference's own failures: what each driver found, in words that claim no more than the sign test shows. */
public final class OwnFailuresText {
    private OwnFailuresText() {
    }

    /** {@code builtinCar}: the reference is the builtin car and the variants its seeded faults, as the paper's are. */
    public static List<String> lines(OwnFailures own, String reference, int replications, boolean builtinCar) {
        List<String> out = new ArrayList<>();
        if (builtinCar) {
            out.add(PairSummary.HEADING + "The reference car's own failures (fault-free runs with an accident)");
            out.add(String.format(Locale.ROOT, "Failures the fault-free car had by itself, not a seeded fault's: %d maps in"
                    + " all, listed in own-failures.csv with the command that replays each. Rates are per million ticks of"
                    + " everything the driver spent; distinct failures count a cell × accident type once.",
                    own.failures().size()));
        } else {
            out.add(PairSummary.HEADING + "The reference controller's own failures (reference runs with an accident or a"
                    + " controller failure)");
            out.add(String.format(Locale.ROOT, "Failures the reference had by itself, not a variant's: %d maps in all, listed"
                    + " in own-failures.csv. Rates are per million ticks of everything the driver spent; distinct failures"
                    + " count a cell × failure type once.", own.failures().size()));
        }
        OwnFailures.DriverRate ref = own.rates().stream().filter(r -> r.driver().equals(reference)).findFirst().orElseThrow();
        for (OwnFailures.DriverRate r : own.rates()) {
            String line = String.format(Locale.ROOT, "- %s: %d failures in %.2f M ticks, %.2f per million ticks; %.2f"
                    + " distinct a replication on average, %d distinct over all %d replications", r.driver(), r.failures(),
                    r.ticks() / 1e6, r.perMillionTicks(), r.distinctMean(), r.distinctPooled(), replications);
            if (!r.driver().equals(reference)) {
                line += "; " + rate(r, ref) + String.format(Locale.ROOT, "; a higher rate than %s in %d replications, a"
                        + " lower one in %d, sign test p = %s: %s", reference, r.higher(), r.lower(), VerdictText.p(r.p()),
                        signTestCanReach(r) ? r.p() < 0.05 ? (r.higher() > r.lower() ? "it finds them more often"
                        : "it finds them less often") : "no difference in rate shown" : "not tested, as so few replications"
                        + " differ that the sign test cannot reach 0.05");
            }
            out.add(line + ".");
        }
        return out;
    }

    /** Whether a sign test over the replications that differ could reach 0.05: its smallest p is 2/2^n. */
    static boolean signTestCanReach(OwnFailures.DriverRate r) {
        return 2 / Math.pow(2, r.higher() + r.lower()) < 0.05;
    }

    /**
     * "above random's rate (×1.24, 95 % CI …)"; where the reference found none there is no ratio, and
     * where neither found any, nothing to compare.
     */
    private static String rate(OwnFailures.DriverRate r, OwnFailures.DriverRate ref) {
        if (ref.perMillionTicks() == 0) {
            return r.perMillionTicks() == 0 ? "none, as " + ref.driver() + " found none" : "above " + ref.driver()
                    + "'s rate, which is 0 (no ratio)";
        }
        return String.format(Locale.ROOT, "%s %s's rate (×%.2f%s)", r.perMillionTicks() >= ref.perMillionTicks() ? "above"
                : "below", ref.driver(), r.perMillionTicks() / ref.perMillionTicks(), ratioInterval(r));
    }

    /** ", 95 % CI 0.61 to 3.20 over replications", or nothing where the ratio has no interval. */
    private static String ratioInterval(OwnFailures.DriverRate r) {
        if (Double.isNaN(r.ratio().low())) {
            return "";
        }
        return String.format(Locale.ROOT, ", 95 %% CI %s to %s over replications", ratio(r.ratio().low()),
                ratio(r.ratio().high()));
    }

    private static String ratio(double v) {
        return Double.isInfinite(v) ? "∞" : String.format(Locale.ROOT, "%.2f", v);
    }
}
