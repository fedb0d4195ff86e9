package sitcov.analysis;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import sitcov.experiment.DriverRun;
import sitcov.experiment.DriverSpend;
import sitcov.experiment.MapId;
import sitcov.experiment.MapRun;
import sitcov.experiment.ReplicationResult;
import sitcov.experiment.StopReason;
import sitcov.judge.RunSummary;
import sitcov.oracle.AccidentType;
import sitcov.oracle.Outcome;

class OwnFailuresTest {
    /** A fault-free run of 100 ticks with these accident counts (obstacle, other car, off road, centre line, timeout). */
    private static MapRun map(int replication, String driver, int index, int cell, long... counts) {
        RunSummary run = new RunSummary(Outcome.TARGET_REACHED, 100, List.of(counts[0], counts[1], counts[2], counts[3],
                counts[4]));
        return new MapRun(replication, driver, index, index, new MapId.Seeded(index), index, index, cell,
                List.of(0.0, 0.0, 0.0), run, List.of());
    }

    private static DriverRun run(String driver, long ticks, MapRun... maps) {
        return new DriverRun(driver, List.of(maps), new DriverSpend(maps.length == 0 ? 0 : maps[0].replication(), driver,
                10, maps.length, ticks, 1, StopReason.TICKS));
    }

    private static final List<ReplicationResult> RESULTS = List.of(
            new ReplicationResult(0, List.of(
                    run("random", 200_000, map(0, "random", 0, 1, 0, 0, 0, 0, 0), map(0, "random", 1, 3, 0, 0, 1, 0, 0)),
                    run("stress-search", 250_000, map(0, "stress-search", 0, 3, 0, 0, 2, 0, 0),
                            map(0, "stress-search", 1, 3, 0, 0, 1, 0, 1), map(0, "stress-search", 2, 5, 0, 1, 0, 0, 0)))),
            new ReplicationResult(1, List.of(
                    run("random", 300_000, map(1, "random", 0, 3, 0, 0, 0, 0, 0)),
                    run("stress-search", 250_000, map(1, "stress-search", 0, 7, 1, 0, 0, 0, 0)))));

    @Test
    void eachDriversOwnFailuresAreCountedPerMillionTicksAndDistinctByCellAndAccidentType() {
        OwnFailures own = OwnFailures.of(RESULTS, List.of("random", "stress-search"), "random", new java.util.SplittableRandom(1));
        assertEquals(5, own.failures().size(), "maps with a fault-free accident");
        assertEquals(List.of(sitcov.oracle.Failure.LEAVEROAD, sitcov.oracle.Failure.TIMEOUT), own.failures().get(2).types());
        OwnFailures.DriverRate random = own.rates().get(0);
        // 1 failure in 500 000 ticks; distinct: {3 off road} then none
        assertEquals(1, random.failures());
        assertEquals(2.0, random.perMillionTicks(), 1e-12);
        assertEquals(0.5, random.distinctMean(), 1e-12);
        assertEquals(1, random.distinctPooled());
        assertTrue(Double.isNaN(random.p()), "the reference is not tested against itself");
        OwnFailures.DriverRate stress = own.rates().get(1);
        // 4 failures in 500 000 ticks; distinct: {3 off road, 3 timeout, 5 other car} then {7 obstacle}
        assertEquals(4, stress.failures());
        assertEquals(8.0, stress.perMillionTicks(), 1e-12);
        assertEquals(2.0, stress.distinctMean(), 1e-12);
        assertEquals(4, stress.distinctPooled());
        // replication 0: 12 against 5 a million ticks; replication 1: 4 against 0 — both higher; p = 2 · ½² = 0.5
        assertEquals(2, stress.higher());
        assertEquals(0, stress.lower());
        assertEquals(0.5, stress.p(), 1e-12);
        // its rate over random's: (4 / 500 000) / (1 / 500 000) = 4; resampling the two replications gives
        // {0,0}: (6 / 500 000) / (2 / 400 000) = 2.4, one of each: 4, {1,1}: random found none, so ∞ —
        // each with a probability of 1/4 or more, so the interval spans 2.4 to ∞
        assertEquals(4.0, stress.ratio().estimate(), 1e-12);
        assertEquals(2.4, stress.ratio().low(), 1e-12);
        assertEquals(Double.POSITIVE_INFINITY, stress.ratio().high());
        assertTrue(Double.isNaN(random.ratio().estimate()), "the reference has no ratio to itself");
    }
}
