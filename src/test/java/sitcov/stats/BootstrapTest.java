package sitcov.stats;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

class BootstrapTest {
    // Efron & Tibshirani, An Introduction to the Bootstrap (1993), Table 2.1: survival times of mice,
    // treatment mean 86.86, control mean 56.22, difference 30.63.
    private static final double[] TREATMENT = {94, 197, 16, 38, 99, 141, 23};
    private static final double[] CONTROL = {52, 104, 146, 10, 51, 30, 40, 27, 46};

    @Test
    void theMouseDataGiveEfronAndTibshiranisDifferenceInsideItsInterval() {
        ConfidenceInterval ci = Bootstrap.meanDifference(TREATMENT, CONTROL, new SplittableRandom(1993));
        assertEquals(30.63, ci.estimate(), 0.005);
        assertTrue(ci.contains(ci.estimate()), ci.toString());
        // Normal-theory SE of the difference is 28.93 (ibid.): the interval must be of that order.
        assertTrue(ci.width() > 2 * 28.93 && ci.width() < 6 * 28.93, ci.toString());
    }

    @Test
    void theSameGeneratorStateGivesTheSameIntervalAndAnotherStateAnotherOne() {
        ConfidenceInterval first = Bootstrap.meanDifference(TREATMENT, CONTROL, new SplittableRandom(42));
        ConfidenceInterval again = Bootstrap.meanDifference(TREATMENT, CONTROL, new SplittableRandom(42));
        ConfidenceInterval other = Bootstrap.meanDifference(TREATMENT, CONTROL, new SplittableRandom(43));
        assertEquals(first, again);
        assertNotEquals(first, other);
        ConfidenceInterval paired = Bootstrap.pairedMeanDifference(CONTROL, CONTROL.clone(), new SplittableRandom(7));
        assertEquals(new ConfidenceInterval(0, 0, 0), paired); // identical pairs: every resample is 0
    }

    // On large samples the percentile interval approaches the normal-theory one, estimate +- 1.96 SE.
    // Tolerance 0.25 SE for each end: with B = 2000 the Monte Carlo standard deviation of a 2.5 %
    // percentile is about sqrt(0.025 * 0.975 / 2000) / phi(1.96) = 0.06 SE, and at n = 2000 the
    // bootstrap's own skewness and (n - 1)/n variance bias are far smaller, so 0.25 SE is ~4 sd.

    @Test
    void onLargeIndependentSamplesTheIntervalApproachesTheNormalTheoryOne() {
        SplittableRandom data = new SplittableRandom(2024);
        double[] x = new double[2000];
        double[] y = new double[2000];
        for (int i = 0; i < x.length; i++) {
            x[i] = data.nextGaussian(10, 2);
            y[i] = data.nextGaussian(9.5, 3);
        }
        double se = Math.sqrt(Descriptive.variance(x) / x.length + Descriptive.variance(y) / y.length);
        double estimate = Descriptive.mean(x) - Descriptive.mean(y);
        ConfidenceInterval ci = Bootstrap.meanDifference(x, y, new SplittableRandom(5));
        assertEquals(estimate, ci.estimate(), 1e-12);
        assertEquals(estimate - 1.959964 * se, ci.low(), 0.25 * se);
        assertEquals(estimate + 1.959964 * se, ci.high(), 0.25 * se);
    }

    @Test
    void onLargePairedSamplesTheIntervalApproachesTheNormalTheoryOne() {
        SplittableRandom data = new SplittableRandom(2025);
        double[] x = new double[2000];
        double[] y = new double[2000];
        double[] d = new double[x.length];
        for (int i = 0; i < x.length; i++) {
            x[i] = data.nextGaussian(10, 3);
            y[i] = x[i] - data.nextGaussian(0.2, 1); // strongly correlated pairs
            d[i] = x[i] - y[i];
        }
        double se = Math.sqrt(Descriptive.variance(d) / d.length);
        ConfidenceInterval ci = Bootstrap.pairedMeanDifference(x, y, new SplittableRandom(6));
        assertEquals(Descriptive.mean(d), ci.estimate(), 1e-12);
        assertEquals(ci.estimate() - 1.959964 * se, ci.low(), 0.25 * se);
        assertEquals(ci.estimate() + 1.959964 * se, ci.high(), 0.25 * se);
        // Pairing removes the shared variation: the unpaired interval on the same data is far wider.
        assertTrue(Bootstrap.meanDifference(x, y, new SplittableRandom(6)).width() > 2 * ci.width());
    }

    @Test
    void noValuesGiveAnIntervalOfNothingAndDrawNothing() {
        SplittableRandom used = new SplittableRandom(9);
        assertSame(Bootstrap.NOTHING, Bootstrap.pairedMeanDifference(new double[0], new double[0], used));
        assertSame(Bootstrap.NOTHING, Bootstrap.meanDifference(new double[0], new double[] {1, 2}, used));
        assertTrue(Double.isNaN(Bootstrap.NOTHING.estimate()) && Double.isNaN(Bootstrap.NOTHING.low())
                && Double.isNaN(Bootstrap.NOTHING.high()));
        assertEquals(new SplittableRandom(9).nextLong(), used.nextLong(), "the stream is where it was");
    }

    @Test
    void aRateRatioOverTwoReplicationsRunsFromTheLeastToTheMostOfItsThreeResampledValues() {
        // replication 0: A 2 events in 100 ticks, B 1 in 100; replication 1: A 0 in 100, B 3 in 100.
        // A resample is {0,0}, {1,1} (each with probability 1/4) or one of each (1/2), with ratios
        // (4/200)/(2/200) = 2, (0/200)/(6/200) = 0 and (2/200)/(4/200) = 0.5: each far more likely than
        // 2.5 %, so in 2000 resamples the 95 % interval is all of [0, 2]; the estimate is 0.5.
        double[] ea = {2, 0};
        double[] xa = {100, 100};
        double[] eb = {1, 3};
        double[] xb = {100, 100};
        ConfidenceInterval ci = Bootstrap.pairedRateRatio(ea, xa, eb, xb, new SplittableRandom(3));
        assertEquals(0.5, ci.estimate(), 1e-12);
        assertEquals(0, ci.low(), 1e-12);
        assertEquals(2, ci.high(), 1e-12);
    }

    @Test
    void aRateRatioWithNoEventsOnEitherSideIsNotEstimated() {
        double[] none = {0, 0};
        double[] ticks = {10, 10};
        assertSame(Bootstrap.NOTHING, Bootstrap.pairedRateRatio(none, ticks, none, ticks, new SplittableRandom(1)));
    }
}
