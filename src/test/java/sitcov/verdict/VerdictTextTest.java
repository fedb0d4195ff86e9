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
    void exploratoryFindingsSayWhatTheirFamilyAllowsAndNotTestableRowsSaySo() {
        String text = String.join("\n", VerdictText.lines(COMPARISON, List.of(), BudgetKind.TICKS));
        // cells covered and the area, p = 0.0196 each, two places of the measures' family: Holm 2 × 0.0196 = 0.039
        assertTrue(text.contains("- cells covered: higher for coverage-filter, 3.00 against 1.00 (+2.00, CI 2.00 to 2.00;"
                + " Holm p = 0.039; coverage-filter higher in 6 of 6 replications, random in 0)."), text);
        assertTrue(text.contains("- maps run: not testable: it is 3 in every replication of both."), text);
        assertTrue(text.contains("Measures (2 of pairs, 2 difference tests)"), text);
        assertTrue(text.contains("Faults (1 test): a screening family under Benjamini-Hochberg"), text);
        // fault 14 alone in the screening: q = p = 0.0196
        assertTrue(text.contains("found on a larger share of coverage-filter's maps: fault 14 (100.0 % of"
                + " coverage-filter's maps against 0.0 % of random's, +100.0 points, CI 100.0 to 100.0; BH q = 0.020)"), text);
        assertTrue(text.contains("not tested: fault 19 (found by neither driver)"), text);
        assertFalse(text.contains("no significant difference"), "no 'no difference' without a margin: " + text);
        assertTrue(text.contains("With 6 paired replications the 95 % CIs only describe"), text);
    }

    @Test
    void fiveReplicationsAreSaidOnceToBeTooFewForAnyRankTestAndTenToFewForCIs() {
        String caveat = Reading.fewReplications(5).orElseThrow();
        assertTrue(caveat.startsWith("Nothing below is tested for a difference: with 5 paired replications no signed-rank"
                + " test can reach p < 0.05 (its smallest two-sided p is 2/2^5 = 0.0625)"), caveat);
        assertTrue(caveat.contains("describe the differences, they do not test them"), caveat);
        assertTrue(Reading.fewReplications(10).orElseThrow().contains("CIs only describe"));
        assertTrue(Reading.fewReplications(11).isEmpty());
    }

    @Test
    void eachPairGetsAHeadingThenItsBottomLineInOneSentence() {
        List<String> lines = VerdictText.lines(COMPARISON, List.of(), BudgetKind.TICKS);
        int heading = lines.indexOf("## coverage-filter against random (6 paired replications)");
        assertTrue(heading > 0, lines.toString());
        // by hand: cells covered, the primary (distinct faults) and the area are higher for coverage-filter, and
        // fault 14 flagged; maps run, faults per map and the all-fault share are not testable
        assertEquals("In short: coverage-filter is ahead on cells covered, distinct faults found (the primary question),"
                + " area under faults found against ticks and fault 14 (found on more of its maps, screening); 3 measures"
                + " not testable.", lines.get(heading + 1));
    }

    @Test
    void wherePairCanReachTheLevelItsBottomLineSaysNothingWasTestedAndDescribesTheLargestDifferences() {
        // five replications, both drivers finding fault 14 on every map: only cells covered differs (by 1..5)
        Comparison five = Comparison.of(ComparisonTest.config(5, List.of("coverage-filter", "random")),
                ComparisonTest.filterAheadByUntiedAmounts(5, "F-"), new SplittableRandom(3));
        List<String> lines = VerdictText.lines(five, List.of(), BudgetKind.TICKS);
        String inShort = lines.get(lines.indexOf("## coverage-filter against random (5 paired replications)") + 1);
        // the filter's cells 2..6, mean 4, random's 1; differences 1..5 (sd 1.581) lie within the margin of ±5:
        // t = (3 - 5) / (1.581 / sqrt 5) = -2.83 on 4 df, one-sided p = 0.024, the measures' family's only place
        assertTrue(inShort.startsWith("In short: no difference tested (with 5 paired replications no signed-rank test can"
                + " reach 5 %); equivalent in cells covered; the largest differences, described: cells covered 4.00 against"
                + " 1.00 (+3.00, CI "), inShort);
        assertFalse(inShort.contains("no difference shown"), inShort);
        assertTrue(lines.get(1).startsWith("Answer: not testable"), lines.get(1));
    }

    @Test
    void testsNoDifferenceCouldPassAtThisNAreSaidOnceNotOnEveryLine() {
        Comparison c = Comparison.of(ComparisonTest.config(6, List.of("coverage-filter", "random")),
                ComparisonTest.filterAheadByUntiedAmounts(6, "--"), new SplittableRandom(3));
        List<String> lines = VerdictText.lines(c, List.of(), BudgetKind.TICKS);
        // cells covered and the area: smallest p 2/2^6 = 0.03125, above 0.05 / 2 places
        assertEquals(1, lines.stream().filter(l -> l.contains("could not have shown a difference, however large")).count());
        assertTrue(lines.stream().anyMatch(l -> l.startsWith("2 of the exploratory tests below (2 of measures, 0 per fault)")),
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
