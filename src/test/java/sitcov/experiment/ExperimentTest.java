package sitcov.experiment;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.random.RandomGenerator;
import org.junit.jupiter.api.Test;
import sitcov.coverage.GridDefinition;
import sitcov.faults.FaultSet;

class ExperimentTest {
    // small enough for the test suite; faults 14 and 19 keep the faulty runs short
    private static final ExperimentConfig TINY = new ExperimentConfig("tiny", 42, 20, 2, FaultSet.parse("14,19"),
            BudgetKind.TICKS, GridDefinition.paper());

    private static final List<ReplicationResult> RESULTS = Experiment.run(TINY, 1, System::nanoTime, r -> { });

    @Test
    void theCoverageFilterNeverRunsTwoMapsOfOneCell() {
        for (ReplicationResult r : RESULTS) {
            Set<Integer> cells = new HashSet<>();
            for (MapRun run : r.runsOf(Method.COVERAGE_FILTER)) {
                assertTrue(cells.add(run.cell()), "cell " + run.cell() + " run twice in replication " + r.replication()
                        + " (master seed " + TINY.masterSeed() + ")");
            }
            assertTrue(cells.size() > 5, "the filter ran only " + cells.size() + " maps of 20 candidates");
        }
    }

    @Test
    void bothDriversDrawTheSameCandidateSequence() {
        for (ReplicationResult r : RESULTS) {
            RandomGenerator expected = Replication.candidates(TINY.masterSeed(), r.replication());
            long[] sequence = new long[200];
            for (int i = 0; i < sequence.length; i++) {
                sequence[i] = expected.nextLong();
            }
            for (MapRun run : r.runs()) {
                assertEquals(sequence[run.candidate()], run.externalSeed(), run.method() + " candidate " + run.candidate()
                        + " of replication " + r.replication());
            }
            // the random driver runs every candidate it draws, in order, from the first
            List<MapRun> random = r.runsOf(Method.RANDOM);
            assertEquals(sequence[0], random.get(0).externalSeed());
        }
    }

    @Test
    void aMapSharedByBothDriversIsRunIdentically() {
        for (ReplicationResult r : RESULTS) {
            for (MapRun c : r.runsOf(Method.COVERAGE_FILTER)) {
                r.runsOf(Method.RANDOM).stream().filter(x -> x.externalSeed() == c.externalSeed()).findFirst()
                        .ifPresent(x -> assertEquals(c.faultFree(), x.faultFree(), "map " + c.externalSeed()));
            }
        }
    }

    @Test
    void underTheTicksBudgetTheRandomDriverSpendsAtLeastWhatTheCoverageDriverSpent() {
        for (ReplicationResult r : RESULTS) {
            long coverage = r.runsOf(Method.COVERAGE_FILTER).stream().mapToLong(MapRun::ticks).sum();
            List<MapRun> random = r.runsOf(Method.RANDOM);
            long spent = random.stream().mapToLong(MapRun::ticks).sum();
            long beforeLast = spent - random.get(random.size() - 1).ticks();
            assertTrue(spent >= coverage && beforeLast < coverage,
                    "random spent " + spent + " ticks (" + beforeLast + " before its last map) against " + coverage);
        }
    }

    @Test
    void resultsDoNotDependOnTheThreadCount() {
        List<ReplicationResult> twoThreads = Experiment.run(TINY, 2, System::nanoTime, r -> { });
        assertEquals(RESULTS.size(), twoThreads.size());
        for (int i = 0; i < RESULTS.size(); i++) {
            assertEquals(RESULTS.get(i).runs().size(), twoThreads.get(i).runs().size());
            for (int k = 0; k < RESULTS.get(i).runs().size(); k++) {
                MapRun a = RESULTS.get(i).runs().get(k);
                MapRun b = twoThreads.get(i).runs().get(k);
                assertEquals(a.externalSeed(), b.externalSeed());
                assertEquals(a.faultFree(), b.faultFree());
                assertEquals(a.verdicts().stream().map(v -> v.detection()).toList(),
                        b.verdicts().stream().map(v -> v.detection()).toList());
            }
        }
    }
}
