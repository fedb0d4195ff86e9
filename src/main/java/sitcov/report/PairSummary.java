package sitcov.report;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import sitcov.experiment.Finding;
import sitcov.experiment.MeasureTest;

/** The heading of one pair's part of a verdict: who it compares, and its findings in one line. */
final class PairSummary {
    private PairSummary() {
    }

    static String heading(List<MeasureTest> pair, int replications) {
        String a = pair.get(0).driverA();
        String b = pair.get(0).driverB();
        Map<String, List<String>> by = new LinkedHashMap<>();
        for (MeasureTest m : pair) {
            String key = switch (m.finding()) {
                case HIGHER_A -> "higher for " + a;
                case HIGHER_B -> "higher for " + b;
                case EQUIVALENT -> "equivalent";
                case INCONCLUSIVE -> "inconclusive";
                case TOO_FEW -> "not tested";
                case NOT_TESTABLE -> "not testable";
            };
            by.computeIfAbsent(m.primary() && m.finding() != Finding.NOT_TESTABLE ? key + " (primary)" : key,
                    k -> new ArrayList<>()).add(name(m));
        }
        List<String> parts = new ArrayList<>();
        by.forEach((finding, measures) -> parts.add(finding + ": " + String.join(", ", measures)));
        return a + " against " + b + " (" + replications + " paired replications) — " + String.join("; ", parts) + ".";
    }

    /** The measure's words without the paper's name in brackets: a summary line is short. */
    private static String name(MeasureTest m) {
        return m.measure().words().replaceFirst(" \\(.*\\)$", "");
    }
}
