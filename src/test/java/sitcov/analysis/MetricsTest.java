package sitcov.analysis;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import sitcov.experiment.MapId;
import sitcov.experiment.MapRun;
import sitcov.faults.Fault;
import sitcov.judge.Detection;
import sitcov.judge.FaultOutcome;
import sitcov.judge.Notion;
import sitcov.judge.RunSummary;
import sitcov.oracle.AccidentType;
import sitcov.oracle.Outcome;

class MetricsTest {
    private static final List<sitcov.judge.Variant> FAULTS = sitcov.experiment.ExperimentConfig.seeded(java.util.EnumSet.copyOf(List.of(Fault.WAYPOINTS_NORTH_EAST, Fault.MARKING_HALF_RANGE,
            Fault.STOPS_TURNING_WHILE_OVERTAKING)));
    private static final RunSummary SAFE = new RunSummary(Outcome.TARGET_REACHED, 100, List.of(0L, 0L, 0L, 0L, 0L));

    /** A map on which each fault is found (F), only by the paper's notion (P), or not at all (-). */
    private static MapRun map(String marks) {
        List<FaultOutcome> outcomes = new ArrayList<>();
        for (int i = 0; i < FAULTS.size(); i++) {
            char m = marks.charAt(i);
            Optional<sitcov.oracle.Failure> accident = m == 'F' ? Optional.of(sitcov.oracle.Failure.LEAVEROAD) : Optional.empty();
            outcomes.add(new FaultOutcome(FAULTS.get(i), SAFE, true, true, 3,
                    m == 'F' ? Detection.FOUND : Detection.EFFECT_NO_FAILURE, accident, m != '-'));
        }
        return new MapRun(0, "random", 0, 0, new MapId.Seeded(1), 1, 1, 0, List.of(0.0, 0.0, 0.0), SAFE, outcomes);
    }

    @Test
    void thePapersMeasuresOnAHandMadeTable() {
        // four maps, three faults: fault 12 is never found by the differential oracle
        List<MapRun> runs = List.of(map("F-F"), map("FPF"), map("---"), map("F-P"));
        Metrics differential = Metrics.of(runs, FAULTS, Notion.DIFFERENTIAL);
        assertEquals(4, differential.maps());
        assertEquals(1, differential.cells(), "all four hand-made maps are in cell 0");
        assertEquals(2.0 / 3, differential.methodPropFault(), 1e-12);
        assertEquals(0, differential.propMapAllFault(), 1e-12);
        assertEquals((2 + 2 + 0 + 1) / 4.0, differential.avgMapFault(), 1e-12);
        assertArrayEquals(new double[] {0.75, 0, 0.5}, differential.perFault(), 1e-12);

        Metrics paper = Metrics.of(runs, FAULTS, Notion.PAPER);
        assertEquals(1, paper.methodPropFault(), 1e-12);
        assertEquals(0.25, paper.propMapAllFault(), 1e-12);
        assertEquals((2 + 3 + 0 + 2) / 4.0, paper.avgMapFault(), 1e-12);
    }

    @Test
    void noMapsGiveZeroesNotNaN() {
        Metrics m = Metrics.of(List.of(), FAULTS, Notion.DIFFERENTIAL);
        assertEquals(0, m.avgMapFault());
        assertEquals(0, m.propMapAllFault());
    }
}
