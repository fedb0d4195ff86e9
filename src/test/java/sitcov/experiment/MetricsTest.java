package sitcov.experiment;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import sitcov.faults.Activation;
import sitcov.faults.Fault;
import sitcov.oracle.Accident;
import sitcov.oracle.AccidentType;
import sitcov.oracle.Outcome;
import sitcov.oracle.RunResult;

class MetricsTest {
    private static final List<Fault> FAULTS = List.of(Fault.WAYPOINTS_NORTH_EAST, Fault.MARKING_HALF_RANGE,
            Fault.STOPS_TURNING_WHILE_OVERTAKING);
    private static final RunResult SAFE = new RunResult(1, 1, Outcome.TARGET_REACHED, List.of(), Map.of(), 100);

    /** A map on which each fault is found (F), only by the paper's notion (P), or not at all (-). */
    private static MapRun map(String marks) {
        List<FaultVerdict> verdicts = new ArrayList<>();
        for (int i = 0; i < FAULTS.size(); i++) {
            char m = marks.charAt(i);
            Fault f = FAULTS.get(i);
            Optional<Accident> accident = m == 'F' ? Optional.of(new Accident(5, AccidentType.LEAVEROAD, 0, 0, -1))
                    : Optional.empty();
            verdicts.add(new FaultVerdict(f, 1, 1, m == 'F' ? Detection.FOUND : Detection.EFFECT_NO_FAILURE, accident,
                    m != '-', new Activation(f, true, true, 1, 3), SAFE));
        }
        return new MapRun(Method.RANDOM, 0, 0, 1, 1, 0, new double[3], SAFE, verdicts, 100);
    }

    @Test
    void thePapersMeasuresOnAHandMadeTable() {
        // four maps, three faults: fault 12 is never found by the differential oracle
        List<MapRun> runs = List.of(map("F-F"), map("FPF"), map("---"), map("F-P"));
        Metrics differential = Metrics.of(runs, FAULTS, false);
        assertEquals(4, differential.maps());
        assertEquals(1, differential.cells(), "all four hand-made maps are in cell 0");
        assertEquals(2.0 / 3, differential.methodPropFault(), 1e-12);
        assertEquals(0, differential.propMapAllFault(), 1e-12);
        assertEquals((2 + 2 + 0 + 1) / 4.0, differential.avgMapFault(), 1e-12);
        assertArrayEquals(new double[] {0.75, 0, 0.5}, differential.perFault(), 1e-12);

        Metrics paper = Metrics.of(runs, FAULTS, true);
        assertEquals(1, paper.methodPropFault(), 1e-12);
        assertEquals(0.25, paper.propMapAllFault(), 1e-12);
        assertEquals((2 + 3 + 0 + 2) / 4.0, paper.avgMapFault(), 1e-12);
    }

    @Test
    void noMapsGiveZeroesNotNaN() {
        Metrics m = Metrics.of(List.of(), FAULTS, false);
        assertEquals(0, m.avgMapFault());
        assertEquals(0, m.propMapAllFault());
    }
}
