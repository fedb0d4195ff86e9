package sitcov.verdict;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import sitcov.analysis.Comparison;
import sitcov.analysis.ComparisonTest;
import sitcov.analysis.SituationFaults;
import sitcov.experiment.BudgetKind;

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
    void eachPairGetsAHeadingThenItsBottomLineInOneSentence() {
        List<String> lines = VerdictText.lines(COMPARISON, List.of(), BudgetKind.TICKS);
        int heading = lines.indexOf("## coverage-filter against random (6 paired replications)");
        assertTrue(heading > 0, lines.toString());
        // by hand: the primary (distinct faults) is higher for coverage-filter; cells covered and area are
        // inconclusive, maps run, faults per map and the all-fault share not testable: 5 show nothing
        assertEquals("In short: coverage-filter is ahead on distinct faults found (the primary question); the other 5"
                + " measures show no difference.", lines.get(heading + 1));
    }

    @Test
    void testsNoDifferenceCouldPassAtThisNAreSaidOnceNotOnEveryLine() {
        List<String> lines = VerdictText.lines(COMPARISON, List.of(), BudgetKind.TICKS);
        // 3 exploratory tests, Holm's first level 0.05/3 < 0.03125, the smallest p of 6 pairs
        assertEquals(1, lines.stream().filter(l -> l.contains("could not have shown a difference, however large")).count());
        assertTrue(lines.stream().anyMatch(l -> l.startsWith("3 of the exploratory tests below (2 of measures, 1 per fault)")),
                lines.toString());
        assertTrue(lines.stream().noneMatch(l -> l.startsWith("- ") && l.contains("at this n")), lines.toString());
    }

    @Test
    void theUniformityHeadlineLeavesOutFaultsTooRareToTestAndNamesItsDenominator() {
        var faults = sitcov.experiment.ExperimentConfig.seeded(java.util.EnumSet.allOf(sitcov.faults.Fault.class)).toArray(sitcov.judge.Variant[]::new);
        List<SituationFaults.Uniformity> tests = List.of(
                new SituationFaults.Uniformity(faults[0], 400, 200, 0.30, 0.10, 0.01),
                new SituationFaults.Uniformity(faults[1], 400, 100, 0.10, 0.10, 0.50),
                new SituationFaults.Uniformity(faults[2], 400, 1, 0.99, 0.20, 0.02),
                new SituationFaults.Uniformity(faults[3], 400, 398, 0.90, 0.30, 0.03),
                new SituationFaults.Uniformity(faults[4], 400, 0, 0, 0, 1));
        String text = VerdictText.uniformity(tests);
        // (0.30 + 0.10) / 2 = 20.0 %, (0.10 + 0.10) / 2 = 10.0 %: the single find's 0.99 is not averaged in
        assertTrue(text.startsWith("Over the 400 distinct maps run (a map run by several drivers counted once), for the 2"
                + " faults found on some maps but not all (faults 0, 1), the coverage cell explains on average 20.0 %"), text);
        assertTrue(text.contains("against 10.0 % when"), text);
        assertTrue(text.contains("for 1 of them more than chance"), text);
        assertTrue(text.endsWith("Left out as too rare to test: fault 2 (found on fewer than 5 maps), fault 3 (missed on"
                + " fewer than 5 maps)."), text);
    }
}
