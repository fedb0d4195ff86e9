package sitcov.figures;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import java.util.function.DoubleUnaryOperator;
import org.junit.jupiter.api.Test;

class BandTest {
    @Test
    void aStepCurveHoldsEachValueUntilTheNextStepAndTheLastForEver() {
        DoubleUnaryOperator curve = Band.steps(new double[] {1, 3, 3, 5}, new double[] {1, 2, 3, 4});
        assertEquals(0, curve.applyAsDouble(0.5), 0, "nothing before the first step");
        assertEquals(1, curve.applyAsDouble(1), 0);
        assertEquals(1, curve.applyAsDouble(2.9), 0);
        assertEquals(3, curve.applyAsDouble(3), 0, "the last of two steps at one place");
        assertEquals(4, curve.applyAsDouble(100), 0, "a stopped curve keeps its value");
    }

    @Test
    void aBandReadsItsCurvesAtEveryStepAndCountsStoppedOnesWithTheValueTheyStoppedAt() {
        double[][] xs = {{1, 2}, {1, 4}, {3}};
        double[][] ys = {{1, 2}, {1, 3}, {1}};
        List<DoubleUnaryOperator> runs = List.of(Band.steps(xs[0], ys[0]), Band.steps(xs[1], ys[1]), Band.steps(xs[2], ys[2]));
        double[] at = Band.breaks(5, List.of(xs));
        assertArrayEquals(new double[] {0, 1, 2, 3, 4, 5}, at, 0);
        Band band = Band.of(at, runs, 2);
        // at 5: the three hold 2, 3 and 1; median 2, quartiles (definition 7 of three) 1.5 and 2.5
        assertEquals(2, band.median()[5], 0);
        assertEquals(1.5, band.lower()[5], 0);
        assertEquals(2.5, band.upper()[5], 0);
        // at 1: 1, 1 and 0
        assertEquals(1, band.median()[1], 0);
        assertEquals(0.5, band.lower()[1], 0);
        assertEquals(0, band.median()[0], 0);
        assertEquals(2, band.allRan(), 0);
        assertArrayEquals(new double[] {0, 1, 2, 3}, Band.breaks(3, List.of(xs)), 0, "the step at 4 is past the end");
    }

    @Test
    void medianCurvesThatAreTheSameFromEndToEndAreNamedTogether() {
        double[] at = {0, 1, 2};
        Band a = new Band(at, new double[3], new double[] {0, 1, 2}, new double[3], 2);
        Band b = new Band(at, new double[3], new double[] {0, 1, 3}, new double[3], 2);
        Band c = new Band(at, new double[] {0, 0, 1}, new double[] {0, 1, 2}, new double[3], 2);
        assertEquals("the medians of x and z are the same", Band.sameMedians(List.of("x", "y", "z"), List.of(a, b, c)));
        assertEquals("the medians of x, y and z are the same", Band.sameMedians(List.of("x", "y", "z"), List.of(a, a, c)));
        assertEquals("", Band.sameMedians(List.of("x", "y"), List.of(a, b)));
        assertEquals("", Band.sameMedians(List.of("x", "y"), List.of(a, new Band(new double[] {0, 1, 3},
                new double[3], new double[] {0, 1, 2}, new double[3], 3))), "the same values at other places differ");
    }
}
