package sitcov.verdict;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import sitcov.analysis.OwnFailures;
import sitcov.stats.ConfidenceInterval;

class OwnFailuresTextTest {
    private static final ConfidenceInterval NONE = new ConfidenceInterval(Double.NaN, Double.NaN, Double.NaN);

    @Test
    void whereNeitherDriverFoundAFailureThereIsNoRatioToWrite() {
        OwnFailures own = new OwnFailures(List.of(), List.of(
                new OwnFailures.DriverRate("coverage-filter", 0, 2_000_000, 0, 0, 0, 0, 0, 1, NONE),
                new OwnFailures.DriverRate("random", 0, 2_000_000, 0, 0, 0, 0, 0, 1, NONE)));
        String text = String.join("\n", OwnFailuresText.lines(own, "random", 2, true));
        assertFalse(text.contains("n/a"), text);
        assertTrue(text.contains("- coverage-filter: 0 failures in 2.00 M ticks, 0.00 per million ticks; 0.00 distinct a"
                + " replication on average, 0 distinct over all 2 replications; none, as random found none;"), text);
    }

    @Test
    void whereOnlyTheReferenceDriverFoundNoneTheRateIsAboveItsZero() {
        OwnFailures own = new OwnFailures(List.of(), List.of(
                new OwnFailures.DriverRate("coverage-filter", 2, 2_000_000, 1, 1, 2, 1, 0, 1, NONE),
                new OwnFailures.DriverRate("random", 0, 2_000_000, 0, 0, 0, 0, 0, 1, NONE)));
        String text = String.join("\n", OwnFailuresText.lines(own, "random", 2, true));
        assertTrue(text.contains("above random's rate, which is 0 (no ratio)"), text);
        // one replication higher, none lower: the sign test's smallest p is 2/2 = 1
        assertTrue(text.contains("sign test p = 1.000: not tested, as so few replications differ that the sign test cannot"
                + " reach 0.05"), text);
        assertFalse(text.contains("(×"), text);
    }
}
