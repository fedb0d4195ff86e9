package sitcov.figures;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;

class AxisTest {
    private static int divisions(Axis axis) {
        return axis.ticks().size() - 1;
    }

    @Test
    void anAxisOfCountsLabelsWholeNumbersOnlyAndEndsAtOrAboveTheDataBelowAQuarterMore() {
        for (int max = 1; max <= 5000; max++) {
            Axis axis = Axis.counts(max);
            for (double t : axis.ticks()) {
                assertEquals(Math.rint(t), t, 0, "count axis to " + max + " labels " + t);
            }
            assertTrue(axis.last() >= max && axis.last() < Axis.MAX_OVERSHOOT * max, max + " -> " + axis);
            assertTrue(max < 4 || divisions(axis) >= 4 && divisions(axis) <= 8, max + " -> " + axis);
        }
        // the faults-vs-ticks axis once ran to 200000 for 107000 ticks (smoke); 5100 ran to 10000
        assertEquals(125000, Axis.counts(107000).last(), 0);
        assertEquals(List.of(0.0, 1000.0, 2000.0, 3000.0, 4000.0, 5000.0, 6000.0), Axis.counts(5100).ticks());
        assertEquals(List.of(0.0, 1.0, 2.0), Axis.counts(2).ticks(), "a small count: a label per unit, no 0.4s");
    }

    @Test
    void anAxisOfValuesTakesRoundStepsFourToEightOfThemAndEndsBelowAQuarterMoreThanTheData() {
        for (double max : new double[] {0.013, 0.32, 0.5, 0.77, 1, 3.3, 7, 9.99, 16, 132000.5, 1.65e6}) {
            Axis axis = Axis.upTo(max);
            assertTrue(axis.last() >= max && axis.last() < Axis.MAX_OVERSHOOT * max, max + " -> " + axis);
            assertTrue(divisions(axis) >= 4 && divisions(axis) <= 8, max + " -> " + axis);
            double step = axis.ticks().get(1);
            double mantissa = step / Math.pow(10, Math.floor(Math.log10(step) + 1e-9));
            assertTrue(List.of(1.0, 2.0, 2.5, 5.0).stream().anyMatch(m -> Math.abs(m - mantissa) < 1e-9), max + " -> " + axis);
        }
        // 0.32 (a share of maps): 0.1 would end at 0.4, exactly 1.25 times; 0.05 steps end at 0.35
        assertEquals(0.35, Axis.upTo(0.32).last(), 1e-12);
    }

    @Test
    void anAxisToTheFaultCountEndsThereAndIsPaddedSoAMarkAtTheCountSitsInsideTheFrame() {
        Axis seven = Axis.toCount(7);
        assertEquals(List.of(0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0), seven.ticks(), "not 0..10 for seven faults");
        assertEquals(7, seven.end(), 0);
        Axis padded = seven.padded();
        assertEquals(seven.ticks(), padded.ticks());
        assertTrue(padded.end() > 7 && padded.end() < 7.5, padded.toString());
        assertEquals(List.of(0.0, 2.0, 4.0, 6.0, 8.0, 10.0, 12.0, 14.0, 16.0, 18.0, 20.0), Axis.toCount(20).ticks());
        Axis thirteen = Axis.toCount(13);
        assertEquals(13, thirteen.last(), 0);
        thirteen.ticks().forEach(t -> assertEquals(Math.rint(t), t, 0));
    }

    @Test
    void everyLabelOfAnAxisHasTheDecimalsItsStepNeedsAndCountsHaveNone() {
        Axis halves = Axis.steps(0.5, 6);
        assertEquals(List.of("0.0", "0.5", "1.0", "3.0"), List.of(halves.label(0), halves.label(0.5), halves.label(1),
                halves.label(3)));
        Axis twentieths = Axis.steps(0.05, 7);
        assertEquals("0.10", twentieths.label(0.1));
        assertEquals("0.35", twentieths.label(0.35));
        Axis thousands = Axis.counts(5100);
        assertEquals("6000", thousands.label(6000));
    }
}
