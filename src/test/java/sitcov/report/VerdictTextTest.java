package sitcov.report;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import sitcov.experiment.Comparison;
import sitcov.experiment.ComparisonTest;

class VerdictTextTest {
    private static final Comparison COMPARISON = Comparison.of(ComparisonTest.filterCoversAndFindsMore(),
            new SplittableRandom(3));

    @Test
    void theVerdictNamesTheWinnerWhereADifferenceIsSignificantAndSaysSoWhereNot() {
        String text = String.join("\n", VerdictText.lines(COMPARISON, List.of()));
        assertTrue(text.contains("- cells covered: higher for coverage-filter, 3.00 against 1.00 (+2.00, CI 2.00 to 2.00;"
                + " p = 0.020; Â12 = 1.00, large)."), text);
        assertTrue(text.contains("- maps run: no significant difference, 3.00 against 3.00"), text);
        assertTrue(text.contains("found on a larger share of maps: fault 14 by coverage-filter (100.0 % of its maps against"
                + " 0.0 %"), text);
        assertTrue(text.contains("fewer than 10 replications"), "six replications: " + text);
    }

    @Test
    void statsCsvHasARowPerMeasureAndPerFaultOfThePair() {
        List<String> rows = StatsCsv.rows(COMPARISON);
        assertEquals(StatsCsv.HEADER, rows.get(0));
        assertEquals(1 + Comparison.Measure.values().length + 2, rows.size());
        int columns = StatsCsv.HEADER.split(",").length;
        rows.forEach(r -> assertEquals(columns, r.split(",", -1).length, r));
        assertTrue(rows.get(1).startsWith("measure,cells_covered,coverage-filter,random,6,3.000000,1.000000,2.000000,"), rows.get(1));
        assertTrue(rows.get(rows.size() - 2).startsWith("fault,fault_14,coverage-filter,random,,,,,,,,,,,18,18,0,18,"),
                rows.get(rows.size() - 2));
    }
}
