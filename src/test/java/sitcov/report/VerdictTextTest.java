package sitcov.report;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import sitcov.experiment.BudgetKind;
import sitcov.experiment.Comparison;
import sitcov.experiment.ComparisonTest;
import sitcov.experiment.Measure;

class VerdictTextTest {
    private static final Comparison COMPARISON = Comparison.of(ComparisonTest.config(6, List.of("coverage-filter", "random")),
            ComparisonTest.filterCoversAndFindsMore(), new SplittableRandom(3));

    @Test
    void theVerdictLeadsWithTheAnswerToThePrimaryQuestion() {
        List<String> lines = VerdictText.lines(COMPARISON, List.of(), BudgetKind.TICKS);
        assertEquals("Primary question (declared in the preset): do coverage-filter and random differ in distinct faults"
                + " found for the same simulated ticks?", lines.get(0));
        assertTrue(lines.get(1).startsWith("Answer: higher for coverage-filter: coverage-filter 1.00 against random 0.000"
                + " (difference +1.00, 95 % CI 1.00 to 1.00; paired signed-rank p = 0.020)"), lines.get(1));
    }

    @Test
    void exploratoryFindingsSayWhatTheFamilyAllowsAndNotTestableRowsSaySo() {
        String text = String.join("\n", VerdictText.lines(COMPARISON, List.of(), BudgetKind.TICKS));
        assertTrue(text.contains("- cells covered: inconclusive, 3.00 against 1.00 (+2.00, CI 2.00 to 2.00; difference Holm"
                + " p = 0.059)"), text);
        assertTrue(text.contains("- maps run: not testable: it is 3 in every replication of both."), text);
        assertTrue(text.contains("the other 3 tests (2 differences of measures, 1 per-fault difference)"), text);
        assertTrue(text.contains("not tested: fault 19 (found by neither driver)"), text);
        assertFalse(text.contains("no significant difference"), "no 'no difference' without a margin: " + text);
        assertFalse(text.contains("Too few replications"), "six replications can reach 0.03125: " + text);
    }

    @Test
    void fiveReplicationsAreSaidOnceToBeTooFewForAnyRankTest() {
        String caveat = VerdictText.fewReplications(5).orElseThrow();
        assertTrue(caveat.contains("with 5 paired replications no signed-rank test can reach p < 0.05 (its smallest"
                + " two-sided p is 2/2^5 = 0.0625)"), caveat);
        assertTrue(caveat.contains("describe the differences, they do not test them"), caveat);
        assertTrue(VerdictText.fewReplications(6).isEmpty());
    }

    @Test
    void statsCsvHasOneSchemaForMeasuresAndFaults() {
        List<String> rows = StatsCsv.rows(COMPARISON);
        assertEquals(StatsCsv.HEADER, rows.get(0));
        assertEquals(1 + Measure.values().length + 2, rows.size());
        int columns = StatsCsv.HEADER.split(",").length;
        rows.forEach(r -> assertEquals(columns, r.split(",", -1).length, r));
        assertTrue(rows.get(1).startsWith("measure,cells_covered,coverage-filter,random,exploratory,inconclusive,,6,3.00000,"
                + "1.00000,2.00000,"), rows.get(1));
        assertTrue(rows.get(3).startsWith("measure,faults_found,coverage-filter,random,primary,higher-a,"), rows.get(3));
        assertTrue(rows.get(rows.size() - 1).startsWith("fault,fault_19,coverage-filter,random,untested,not-testable,"
                + "found by neither driver,6,"), rows.get(rows.size() - 1));
    }
}
