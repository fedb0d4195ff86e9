package sitcov.analysis;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import sitcov.experiment.DriverRun;
import sitcov.experiment.DriverSpend;
import sitcov.experiment.MapId;
import sitcov.experiment.MapRun;
import sitcov.experiment.StopReason;
import sitcov.faults.Fault;
import sitcov.judge.Detection;
import sitcov.judge.FaultOutcome;
import sitcov.judge.RunSummary;
import sitcov.oracle.AccidentType;
import sitcov.oracle.Outcome;

class DiscoveryTest {
    static final List<sitcov.judge.Variant> FAULTS = List.of(new sitcov.judge.Variant.Seeded(Fault.TARGET_LANE_CHECK_SKIPPED),
            new sitcov.judge.Variant.Seeded(Fault.ONCOMING_AT_HALF_SPEED));
    static final RunSummary SAFE = new RunSummary(Outcome.TARGET_REACHED, 100, List.of(0L, 0L, 0L, 0L, 0L));

    /** Map {@code index} (candidate {@code candidate}) in {@code cell}; per fault F found, - not; each map costs 300 ticks. */
    static MapRun map(String driver, int index, int candidate, int cell, String marks) {
        List<FaultOutcome> faults = new ArrayList<>();
        for (int f = 0; f < FAULTS.size(); f++) {
            boolean found = marks.charAt(f) == 'F';
            faults.add(new FaultOutcome(FAULTS.get(f), SAFE, true, true, 1, found ? Detection.FOUND : Detection.EFFECT_NO_FAILURE,
                    found ? Optional.of(sitcov.oracle.Failure.LEAVEROAD) : Optional.empty(), found));
        }
        return new MapRun(0, driver, index, candidate, new MapId.Seeded(candidate), candidate, candidate, cell,
                List.of(0.0, 0.0, 0.0), SAFE, faults);
    }

    static DriverRun run(String driver, MapRun... maps) {
        long ticks = List.of(maps).stream().mapToLong(MapRun::ticks).sum();
        return new DriverRun(driver, List.of(maps), new DriverSpend(0, driver, 10, maps.length, ticks,
                (int) List.of(maps).stream().mapToInt(MapRun::cell).distinct().count(), StopReason.CANDIDATES));
    }

    @Test
    void aFaultCountsAsFoundWithTheWholeOfTheMapThatFoundIt() {
        // three maps of 300 ticks each (fault-free 100, two faulty runs of 100); fault 14 first found on
        // the second map (drawn as candidate 4), fault 19 never
        Discovery d = Discovery.of(run("coverage-filter", map("coverage-filter", 0, 1, 3, "--"),
                map("coverage-filter", 1, 4, 5, "F-"), map("coverage-filter", 2, 7, 6, "F-")), FAULTS);
        assertEquals(600, d.ticksAtFirst(0));
        assertEquals(5, d.candidatesAtFirst(0), "candidates 0..4 were drawn");
        assertEquals(Discovery.NEVER, d.ticksAtFirst(1));
        assertEquals(900, d.ticksSpent());
        assertEquals(List.of(0, 1, 1), List.of(d.foundBy(599), d.foundBy(600), d.foundBy(900)));
    }

    @Test
    void theAreaUnderTheDiscoveryCurveIsTheShareOfTheRectangleOfAllFaultsFromTheStart() {
        Discovery d = Discovery.of(run("random", map("random", 0, 0, 3, "--"), map("random", 1, 1, 3, "F-"),
                map("random", 2, 2, 3, "FF")), FAULTS);
        // fault 14 from tick 600, fault 19 from tick 900: over 900 ticks, (300 + 0) / (900 * 2)
        assertEquals(300.0 / 1800, d.area(900), 1e-12);
        // over a horizon of 1200 ticks: (600 + 300) / (1200 * 2)
        assertEquals(900.0 / 2400, d.area(1200), 1e-12);
        assertEquals(0, d.area(0));
    }
}
