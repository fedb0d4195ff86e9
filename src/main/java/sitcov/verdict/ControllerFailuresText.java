package sitcov.verdict;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import sitcov.analysis.ControllerFailures;

/**
 * The verdict's first lines when controllers failed: a reference that failed on every map is said
 * first, since nothing after it is about driving; otherwise how often each controller failed, which
 * the differential oracle counts as a failure like an accident.
 */
public final class ControllerFailuresText {
    private ControllerFailuresText() {
    }

    /** Nothing when no controller failed. */
    public static List<String> lines(ControllerFailures c) {
        List<String> out = new ArrayList<>();
        if (!c.any()) {
            return out;
        }
        if (c.referenceAlwaysFailed()) {
            out.add(String.format(Locale.ROOT, "THE REFERENCE CONTROLLER FAILED ON EVERY MAP: all %d reference runs ended in"
                    + " %s, so it never drove and nothing below measures driving. Read the reason in runs.csv's"
                    + " controller_failure column and the controller's stderr in controller-N.log, fix the controller,"
                    + " and run again.", c.maps(), kinds(c.reference())));
        }
        List<String> parts = new ArrayList<>();
        parts.add(String.format(Locale.ROOT, "the reference on %d of %d maps%s", c.reference().total(), c.maps(),
                c.reference().total() == 0 ? "" : " (" + kinds(c.reference()) + ")"));
        for (ControllerFailures.VariantCount v : c.variants()) {
            parts.add(String.format(Locale.ROOT, "variant %d (%s) on %d%s", v.variant().id(), v.variant().label(),
                    v.count().total(), v.count().total() == 0 ? "" : " (" + kinds(v.count()) + ")"));
        }
        out.add("Controller failures (no command in time, an exit, garbage; each counts as a failure, as an accident does):"
                + " " + String.join("; ", parts) + ".");
        return out;
    }

    private static String kinds(ControllerFailures.Count n) {
        List<String> k = new ArrayList<>();
        if (n.errors() > 0) {
            k.add(n.errors() + " CONTROLLER_ERROR");
        }
        if (n.timeouts() > 0) {
            k.add(n.timeouts() + " CONTROLLER_TIMEOUT");
        }
        return String.join(", ", k);
    }
}
