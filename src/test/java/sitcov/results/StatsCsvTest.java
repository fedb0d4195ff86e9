package sitcov.results;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import sitcov.analysis.Comparison;
import sitcov.analysis.ComparisonTest;
import sitcov.experiment.Measure;

class StatsCsvTest {
    private static final Comparison COMPARISON = Comparison.of(ComparisonTest.config(6, List.of("coverage-filter", "random")),
            ComparisonTest.filterCoversAndFindsMore(), new SplittableRandom(3));

    @Test
    void hasOneSchemaForMeasuresAndFaults() {
        List<String> rows = StatsCsv.rows(COMPARISON);
        assertEquals(StatsCsv.HEADER, rows.get(0));
        assertEquals(1 + Measure.PAPER.size() + 2, rows.size());
        int columns = StatsCsv.HEADER.split(",").length;
        rows.forEach(r -> assertEquals(columns, r.split(",", -1).length, r));
        // cells covered: +2 in all six replications (higher_a 6, higher_b 0, superiority 1); p 0.0197, closed Holm
        // over the measures' two places 0.0393
        assertTrue(rows.get(1).startsWith("measure,cells_covered,coverage-filter,random,exploratory,higher-a,,6,3.00000,"
                + "1.00000,2.00000,2.00000,2.00000,0.00000,6,6,0,1.00000,0.0196562,0.0196562,0.0393123,closed-holm,"), rows.get(1));
        assertTrue(rows.get(3).contains(",none,"), "the primary's p is its own: " + rows.get(3));
        assertTrue(rows.get(rows.size() - 2).startsWith("fault,fault_14,coverage-filter,random,exploratory,higher-a,"),
                rows.get(rows.size() - 2));
        assertTrue(rows.get(rows.size() - 2).contains(",0.0196562,0.0196562,0.0196562,bh,"), "BH over one test: q = p");
        assertTrue(rows.get(3).startsWith("measure,faults_found,coverage-filter,random,primary,higher-a,"), rows.get(3));
        assertTrue(rows.get(rows.size() - 1).startsWith("fault,fault_19,coverage-filter,random,untested,not-testable,"
                + "found by neither driver,6,"), rows.get(rows.size() - 1));
    }
}
