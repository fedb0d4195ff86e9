package sitcov.experiment;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.random.RandomGenerator;
import org.junit.jupiter.api.Test;
import sitcov.coverage.GridDefinition;
import sitcov.drivers.Drivers;
import sitcov.faults.FaultSet;
import sitcov.judge.FaultyRuns;

class ExperimentTest {
    // small enough for the test suite; faults 14 and 19 keep the faulty runs short
    private static final ExperimentConfig TINY = new ExperimentConfig("tiny", 42, 20, 2, FaultSet.parse("14,19"),
            BudgetKind.TICKS, GridDefinition.paper(), List.of("coverage-filter", "random", "every-other"), List.of(), 200,
            FaultyRuns.UNTIL_VERDICT);

    private static final List<ReplicationResult> RESULTS = ResultsCollector.run(TINY, Drivers.standard(), 1);

    @Test
    void everyReplicationHasEveryDriverInThePresetsOrder() {
        assertEquals(2, RESULTS.size());
        for (ReplicationResult r : RESULTS) {
            assertEquals(TINY.drivers(), r.drivers().stream().map(DriverRun::driver).toList());
        }
    }

    @Test
    void theCoverageFilterNeverRunsTwoMapsOfOneCell() {
        for (ReplicationResult r : RESULTS) {
            Set<Integer> cells = new HashSet<>();
            for (MapRun run : r.of("coverage-filter").maps()) {
                assertTrue(cells.add(run.cell()), "cell " + run.cell() + " run twice in replication " + r.replication()
                        + " (master seed " + TINY.masterSeed() + ")");
            }
            assertTrue(cells.size() > 5, "the filter ran only " + cells.size() + " maps of 20 candidates");
        }
    }

    @Test
    void everyDriverDrawsTheSameCandidateSequence() {
        for (ReplicationResult r : RESULTS) {
            RandomGenerator expected = SeedPlan.candidates(TINY.masterSeed(), r.replication());
            long[] sequence = new long[TINY.candidateLimit()];
            for (int i = 0; i < sequence.length; i++) {
                sequence[i] = expected.nextLong();
            }
            for (DriverRun d : r.drivers()) {
                for (MapRun run : d.maps()) {
                    assertEquals(sequence[run.candidate()], run.externalSeed(), d.driver() + " candidate " + run.candidate()
                            + " of replication " + r.replication());
                    assertEquals(new MapId.Seeded(run.externalSeed()), run.map());
                }
            }
            // the random driver runs every candidate it draws, in order, from the first
            assertEquals(sequence[0], r.of("random").maps().get(0).externalSeed());
        }
    }

    @Test
    void aMapSharedByTwoDriversIsRunIdentically() {
        int shared = 0;
        for (ReplicationResult r : RESULTS) {
            for (MapRun c : r.of("coverage-filter").maps()) {
                for (MapRun x : r.of("random").maps()) {
                    if (x.externalSeed() == c.externalSeed()) {
                        assertEquals(c.faultFree(), x.faultFree(), "map " + c.map().text());
                        assertEquals(c.faults(), x.faults(), "map " + c.map().text());
                        assertEquals(c.internalSeed(), x.internalSeed());
                        shared++;
                    }
                }
            }
        }
        assertTrue(shared >= 2, "only " + shared + " maps were run by both drivers; the test needs some");
    }

    @Test
    void underTheTicksBudgetEachLaterDriverSpendsJustPastWhatTheFirstSpent() {
        for (ReplicationResult r : RESULTS) {
            long first = r.drivers().get(0).spend().ticks();
            for (DriverRun d : r.drivers().subList(1, r.drivers().size())) {
                List<MapRun> maps = d.maps();
                long spent = maps.stream().mapToLong(MapRun::ticks).sum();
                long beforeLast = spent - maps.get(maps.size() - 1).ticks();
                assertEquals(spent, d.spend().ticks());
                assertEquals(StopReason.TICKS, d.spend().stoppedBy(), d.driver());
                assertTrue(spent >= first && beforeLast < first,
                        d.driver() + " spent " + spent + " ticks (" + beforeLast + " before its last map) against " + first);
            }
            assertEquals(StopReason.CANDIDATES, r.drivers().get(0).spend().stoppedBy());
            assertEquals(TINY.candidates(), r.drivers().get(0).spend().candidates());
        }
    }

    @Test
    void theEveryOtherDriverRunsOnlyCandidatesAtEvenPositions() {
        for (ReplicationResult r : RESULTS) {
            List<MapRun> maps = r.of("every-other").maps();
            assertTrue(maps.size() > 3);
            for (int i = 0; i < maps.size(); i++) {
                assertEquals(0, maps.get(i).candidate() % 2, "map " + i);
                assertEquals(i, maps.get(i).mapIndex());
            }
        }
    }

    @Test
    void aLaterDriverThatRunsTooFewMapsStopsAtTheCandidateLimit() {
        // the filter reads the same 8 candidates as random but skips repeated cells, so it cannot spend as much
        ExperimentConfig config = new ExperimentConfig("limit", 42, 8, 1, FaultSet.parse("19"), BudgetKind.TICKS,
                GridDefinition.paper(), List.of("random", "coverage-filter"), List.of(), 8, FaultyRuns.UNTIL_VERDICT);
        ReplicationResult r = ResultsCollector.run(config, Drivers.standard(), 1).get(0);
        DriverSpend filter = r.of("coverage-filter").spend();
        assertEquals(StopReason.CANDIDATE_LIMIT, filter.stoppedBy());
        assertEquals(8, filter.candidates());
        assertTrue(filter.ticks() < r.of("random").spend().ticks(), filter + " against " + r.of("random").spend());
    }

    @Test
    void resultsDoNotDependOnTheThreadCount() {
        List<ReplicationResult> twoThreads = ResultsCollector.run(TINY, Drivers.standard(), 2);
        assertEquals(RESULTS, twoThreads);
    }
}
