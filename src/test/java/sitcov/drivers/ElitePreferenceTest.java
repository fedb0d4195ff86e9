package sitcov.drivers;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import org.junit.jupiter.api.Test;
import sitcov.coverage.GridDefinition;
import sitcov.experiment.BudgetKind;
import sitcov.experiment.DriverRun;
import sitcov.experiment.ExperimentConfig;
import sitcov.experiment.MapId;
import sitcov.experiment.MapRun;
import sitcov.experiment.ReplicationResult;
import sitcov.experiment.ResultsCollector;
import sitcov.faults.Fault;
import sitcov.faults.FaultSet;
import sitcov.judge.Detection;
import sitcov.judge.FaultOutcome;
import sitcov.judge.FaultyRuns;
import sitcov.judge.RunSummary;
import sitcov.oracle.AccidentType;
import sitcov.oracle.Outcome;

class ElitePreferenceTest {
    private static final List<Fault> FAULTS = List.of(Fault.WAYPOINTS_NORTH_EAST, Fault.MARKING_HALF_RANGE,
            Fault.STOPS_TURNING_WHILE_OVERTAKING);
    private static final RunSummary SAFE = new RunSummary(Outcome.TARGET_REACHED, 100, List.of(0L, 0L, 0L, 0L, 0L));

    /** A map in {@code cell} on which each fault is found by the differential oracle (F) or not (-). */
    private static MapRun map(int cell, String marks) {
        List<FaultOutcome> outcomes = new ArrayList<>();
        for (int i = 0; i < FAULTS.size(); i++) {
            boolean found = marks.charAt(i) == 'F';
            outcomes.add(new FaultOutcome(new sitcov.judge.Variant.Seeded(FAULTS.get(i)), SAFE, true, found, found ? 3 : -1,
                    found ? Detection.FOUND : Detection.REACHED_NO_EFFECT,
                    found ? Optional.of(sitcov.oracle.Failure.LEAVEROAD) : Optional.empty(), found));
        }
        return new MapRun(0, "fault-search", cell, cell, new MapId.Seeded(cell), 1, 1, cell, List.of(0.0, 0.0, 0.0), SAFE, outcomes);
    }

    @Test
    void anEliteWhoseMapAloneFoundAFaultWeighsMoreThanOneWhoseFaultsManyMapsFound() {
        ElitePreference rare = new ElitePreference.RareFaults();
        rare.ran(0, map(0, "F--"));
        rare.ran(1, map(1, "F--"));
        rare.ran(2, map(2, "FF-"));
        rare.ran(3, map(3, "---"));
        // by hand: the first fault was found on 3 maps, the second on 1
        assertEquals(1 + 10.0 / 3, rare.weight(0), 1e-12);
        assertEquals(1 + 10.0 / 3 + 10.0 / 1, rare.weight(2), 1e-12);
        assertEquals(1, rare.weight(3), 1e-12, "a map that found nothing");
        assertEquals(1, rare.weight(9), 1e-12, "a cell not run");
        assertTrue(!rare.even());
        assertEquals(1, ElitePreference.EVEN.weight(2), 1e-12);
    }

    @Test
    void faultSearchRunsEditedSituationsUnderItsOwnNamesTheSameOnEveryRun() {
        ExperimentConfig config = new ExperimentConfig("fault-search", 42, 150, 1, FaultSet.parse("16,17"),
                BudgetKind.TICKS, GridDefinition.paper(), List.of("fault-search"), List.of(), 150, FaultyRuns.UNTIL_VERDICT);
        List<ReplicationResult> results = ResultsCollector.run(config, Drivers.standard(), 1);
        DriverRun run = results.get(0).of("fault-search");
        Set<Integer> cells = new HashSet<>();
        long edited = run.maps().stream().filter(m -> m.map() instanceof MapId.Situation s
                && s.name().startsWith("fault-search-r0-")).count();
        run.maps().forEach(m -> assertTrue(cells.add(m.cell()), "cell " + m.cell() + " run twice (master seed 42)"));
        assertTrue(edited > 0, "no edited situation reached a new cell (master seed 42)");
        assertEquals(150, run.spend().candidates());
        assertEquals(results, ResultsCollector.run(config, Drivers.standard(), 2));
    }
}
