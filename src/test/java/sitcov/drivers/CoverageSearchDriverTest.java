package sitcov.drivers;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.random.RandomGenerator;
import org.junit.jupiter.api.Test;
import sitcov.coverage.GridDefinition;
import sitcov.experiment.BudgetKind;
import sitcov.experiment.DriverRun;
import sitcov.experiment.ExperimentConfig;
import sitcov.experiment.MapId;
import sitcov.experiment.MapRun;
import sitcov.experiment.ReplicationResult;
import sitcov.experiment.ResultsCollector;
import sitcov.experiment.SeedPlan;
import sitcov.faults.FaultSet;
import sitcov.judge.FaultyRuns;

class CoverageSearchDriverTest {
    // the search alone, 150 candidates: enough for its first elites to be edited into new cells
    private static final ExperimentConfig SEARCH = new ExperimentConfig("search", 42, 150, 1, FaultSet.parse("19"),
            BudgetKind.TICKS, GridDefinition.paper(), List.of("coverage-search"), List.of(), 150, FaultyRuns.UNTIL_VERDICT);

    @Test
    void theSearchRunsEditedSituationsOnlyInCellsNotYetCoveredAndDrawsRandomOnesInStreamOrder() {
        List<ReplicationResult> results = ResultsCollector.run(SEARCH, Drivers.standard(), 1);
        DriverRun run = results.get(0).of("coverage-search");
        Set<Integer> cells = new HashSet<>();
        int edited = 0;
        RandomGenerator stream = SeedPlan.candidates(SEARCH.masterSeed(), 0);
        long[] sequence = new long[SEARCH.candidateLimit()];
        for (int i = 0; i < sequence.length; i++) {
            sequence[i] = stream.nextLong();
        }
        for (MapRun m : run.maps()) {
            assertTrue(cells.add(m.cell()), "cell " + m.cell() + " run twice (master seed " + SEARCH.masterSeed() + ")");
            if (m.map() instanceof MapId.Situation s) {
                edited++;
                assertTrue(s.name().startsWith("search-r0-"), s.name());
                assertTrue(m.candidate() >= 0, "built in place of a candidate of the stream");
            } else {
                assertEquals(sequence[m.candidate()], m.externalSeed(), "a random candidate keeps its place in the stream");
            }
        }
        assertTrue(edited > 0, "no edited situation reached a new cell in " + run.spend().candidates() + " candidates");
        assertEquals(150, run.spend().candidates(), "every edit tried is paid for with a candidate");
        List<Integer> order = run.maps().stream().map(MapRun::candidate).toList();
        assertEquals(order.stream().sorted().toList(), order, "maps run in the order of the candidates they used");
    }

    @Test
    void theSearchIsTheSameOnEveryRun() {
        assertEquals(ResultsCollector.run(SEARCH, Drivers.standard(), 1), ResultsCollector.run(SEARCH, Drivers.standard(), 2));
    }
}
