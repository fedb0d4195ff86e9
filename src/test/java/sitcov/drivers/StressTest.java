package sitcov.drivers;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import org.junit.jupiter.api.Test;
import sitcov.oracle.Margins;

class StressTest {
    private static final double INF = Double.POSITIVE_INFINITY;
    private static final List<Double> NEAR = List.of(1.0, INF, 0.2, 0.05, 10.0, 5.0);

    @Test
    void stressIsTheLeastRobustnessInUnitsOfEachTypesTypicalMargin() {
        // obstacle inf, other car 0.5 m / 1 m, edge 0.1 m / 0.2 m, centre line 0.01 m / 0.05 m, 2350 / 4700 ticks
        Margins m = new Margins(NEAR, List.of(INF, 0.5, 0.1, 0.01, 2350.0));
        assertEquals(0.2, Stress.of(m), 1e-12);
    }

    @Test
    void aFailureIsNegativeAndAnUnknownMarginIsLeftOut() {
        assertEquals(-0.5, Stress.of(new Margins(NEAR, List.of(INF, 0.5, -0.1, 0.01, Double.NaN))), 1e-12);
        assertEquals(INF, Stress.of(Margins.UNKNOWN));
    }

    @Test
    void oneRequirementsStressIsItsOwnRobustnessInItsUnit() {
        Margins m = new Margins(NEAR, List.of(INF, 0.5, 0.1, 0.01, Double.NaN));
        assertEquals(0.5, Stress.of(m, sitcov.oracle.AccidentType.LEAVEROAD), 1e-12, "0.1 m / 0.2 m");
        assertEquals(0.2, Stress.of(m, sitcov.oracle.AccidentType.CROSSCENTRELINE), 1e-12, "0.01 m / 0.05 m");
        assertEquals(INF, Stress.of(m, sitcov.oracle.AccidentType.TIMEOUT), "not known");
    }
}
