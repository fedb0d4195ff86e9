package sitcov.verdict;

import java.util.ArrayList;
import java.util.List;
import sitcov.experiment.ExperimentConfig;
import sitcov.judge.Variant;

/**
 * The verdict's key to the variants, when they are not the builtin car's seeded faults: the tables
 * and tests below name each variant by its id where they would name a fault, so the key says which
 * controller each id is.
 */
public final class VariantsText {
    private VariantsText() {
    }

    /** Nothing for the builtin car's seeded faults, whose ids the fault catalogue explains. */
    public static List<String> lines(ExperimentConfig config) {
        List<String> out = new ArrayList<>();
        if (config.controller().equals(ExperimentConfig.BUILTIN) && config.onlySeeded()) {
            return out;
        }
        if (config.variants().isEmpty()) {
            out.add("Reference " + config.controller() + ", no variants: the experiment seeks the reference's own failures"
                    + " (below).");
            return out;
        }
        List<String> keys = new ArrayList<>();
        for (Variant v : config.variants()) {
            keys.add(v.id() + " = " + v.label() + " (" + v.spec() + ")");
        }
        out.add("Reference " + config.controller() + "; its variants, each named by its id where the tables and tests"
                + " below say \"fault\": " + String.join("; ", keys) + ".");
        return out;
    }
}
