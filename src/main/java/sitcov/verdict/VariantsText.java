package sitcov.verdict;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import sitcov.analysis.VariantFindings;
import sitcov.experiment.ExperimentConfig;
import sitcov.judge.Variant;
import sitcov.oracle.Failure;

/**
 * The verdict's account of the variants when they are not the builtin car's seeded faults compared
 * by two or more drivers (the paper's experiment, whose ids the fault catalogue explains): a key to
 * which controller each id is (the verdict calls them variants, the files' columns faults), and each
 * variant against the reference — where it failed and the reference did not, and the other way round.
 */
public final class VariantsText {
    private VariantsText() {
    }

    /** Whether the verdict gives the variants' key and findings (not for the paper's kind of experiment). */
    public static boolean shown(ExperimentConfig config) {
        return !config.onBuiltinFaults() || config.drivers().size() < 2;
    }

    public static List<String> lines(ExperimentConfig config, VariantFindings findings) {
        List<String> out = new ArrayList<>();
        if (!shown(config)) {
            return out;
        }
        if (config.variants().isEmpty()) {
            out.add("Reference " + config.controller() + ", no variants: the experiment seeks the reference's own failures"
                    + " (below).");
            return out;
        }
        List<String> keys = new ArrayList<>();
        for (Variant v : config.variants()) {
            keys.add(v.id() + " = " + v.label() + (v.label().equals(v.spec()) ? "" : " (" + v.spec() + ")"));
        }
        out.add("Reference " + config.controller() + "; its variants, named below by their ids (which the files' fault"
                + " columns hold): " + String.join("; ", keys) + ".");
        out.add(PairSummary.HEADING + "Each variant against the reference (distinct maps judged, all drivers)");
        for (VariantFindings.Row r : findings.rows()) {
            out.add(row(r));
        }
        return out;
    }

    private static String row(VariantFindings.Row r) {
        String line = String.format(Locale.ROOT, "- variant %d (%s): fails where the reference did not on %d of %d maps",
                r.variant().id(), r.variant().label(), r.regressed(), r.maps());
        if (r.maps() > 0) {
            line += String.format(Locale.ROOT, " (%.1f %%, 95 %% CI %.1f-%.1f %%)", 100 * r.regressedShare().estimate(),
                    100 * r.regressedShare().low(), 100 * r.regressedShare().high());
        }
        if (!r.byFailure().isEmpty()) {
            List<String> by = new ArrayList<>();
            for (Map.Entry<Failure, Long> e : r.byFailure().entrySet()) {
                by.add(e.getKey() + " " + e.getValue());
            }
            line += ", first new failure " + String.join(", ", by) + "; first maps "
                    + String.join(", ", r.firstRegressed().stream().map(m -> m.text()).toList());
        }
        line += String.format(Locale.ROOT, "; the reference failed where it did not fail at all on %d; McNemar's exact test"
                + " on those %d against %d maps, p = %s: %s.", r.improved(), r.regressed(), r.improved(),
                VerdictText.p(r.mcNemarP()), r.regressed() + r.improved() == 0 ? "they fail on the same maps"
                        : r.mcNemarP() < 0.05 ? (r.regressed() > r.improved() ? "it fails more often than the reference"
                        : "it fails less often than the reference") : "no difference shown");
        return line;
    }
}
