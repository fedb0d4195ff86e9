package sitcov.experiment;

import sitcov.builtin.BuiltinCar;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import sitcov.coverage.GridDefinition;
import sitcov.faults.FaultSet;
import sitcov.judge.FaultyRuns;

/** A resumed session judges the journal's maps by reading them back, and refuses a journal its run disagrees with. */
class JournalReplayTest {
    private static final ExperimentConfig CONFIG = new ExperimentConfig("replayed", 11, 6, 1, FaultSet.parse("19"),
            BudgetKind.TICKS, GridDefinition.paper(), List.of("a", "b"), List.of(), 30, FaultyRuns.UNTIL_VERDICT);
    /** Runs every runnable candidate it draws. */
    private static final DriverFactory EVERY_RUNNABLE = name -> session -> {
        while (session.budgetLeft()) {
            Candidate c = session.nextCandidate();
            if (c.runnable()) {
                session.run(c);
            }
        }
    };

    private static List<ExperimentEvent> run(Journal journal) {
        List<ExperimentEvent> events = new ArrayList<>();
        new ExperimentRunner(CONFIG, EVERY_RUNNABLE, Shard.WHOLE, journal, 1, System::nanoTime, List.of(events::add), BuiltinCar.SOURCE)
                .run();
        return events;
    }

    private static List<ExperimentEvent.MapJudged> judged(List<ExperimentEvent> events) {
        return events.stream().filter(ExperimentEvent.MapJudged.class::isInstance)
                .map(ExperimentEvent.MapJudged.class::cast).toList();
    }

    private static List<DriverSpend> spends(List<ExperimentEvent> events) {
        return events.stream().filter(ExperimentEvent.DriverDone.class::isInstance)
                .map(e -> ((ExperimentEvent.DriverDone) e).spend()).toList();
    }

    /** A journal of the first driver's first {@code maps} maps, as the uninterrupted run judged them. */
    private static Journal firstMaps(List<ExperimentEvent.MapJudged> judged, int maps) {
        Journal journal = Journal.empty();
        judged.stream().filter(j -> j.run().driver().equals("a")).limit(maps)
                .forEach(j -> journal.add(new Journal.Entry(j.run(), j.mapNanos(), j.driverNanos())));
        return journal;
    }

    @Test
    void aResumedRunReadsTheJournalsMapsBackAndEndsWhereAnUninterruptedRunEnds() {
        List<ExperimentEvent> whole = run(Journal.empty());
        List<ExperimentEvent.MapJudged> judged = judged(whole);
        assertTrue(judged.stream().filter(j -> j.run().driver().equals("a")).count() >= 2,
                "the test needs a first driver with two maps or more");

        List<ExperimentEvent> resumed = run(firstMaps(judged, 2));
        List<ExperimentEvent.MapJudged> again = judged(resumed);
        assertEquals(judged.stream().map(ExperimentEvent.MapJudged::run).toList(),
                again.stream().map(ExperimentEvent.MapJudged::run).toList());
        assertEquals(List.of(true, true), again.stream().limit(2).map(ExperimentEvent.MapJudged::resumed).toList());
        assertFalse(again.get(2).resumed(), "past the journal the maps are judged now");
        assertEquals(judged.get(1).driverNanos(), again.get(1).driverNanos(), "a replayed map keeps the journal's time");
        assertEquals(spends(whole), spends(resumed));
    }

    @Test
    void aJournalTheRunDisagreesWithIsRefusedNamingTheMap() {
        MapRun first = judged(run(Journal.empty())).get(0).run();
        MapRun other = new MapRun(first.replication(), first.driver(), 0, first.candidate() + 1, first.map(),
                first.externalSeed(), first.internalSeed(), first.cell(), first.criteria(), first.faultFree(),
                first.faults());
        Journal journal = Journal.empty();
        journal.add(new Journal.Entry(other, 1, 1));
        IllegalStateException e = assertThrows(IllegalStateException.class, () -> run(journal));
        assertTrue(e.getMessage().contains("the journal does not match this run: map 0 of driver a"), e.getMessage());
    }
}
