package sitcov.stats;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

class KaplanMeierTest {
    /** Freireich et al. (1963): weeks in remission on 6-MP; false marks a censored time. */
    static List<KaplanMeier.Observation> sixMp() {
        double[] t = {6, 6, 6, 6, 7, 9, 10, 10, 11, 13, 16, 17, 19, 20, 22, 23, 25, 32, 32, 34, 35};
        int[] e = {1, 1, 1, 0, 1, 0, 1, 0, 0, 1, 1, 0, 0, 0, 1, 1, 0, 0, 0, 0, 0};
        List<KaplanMeier.Observation> out = new ArrayList<>();
        for (int i = 0; i < t.length; i++) {
            out.add(new KaplanMeier.Observation(t[i], e[i] == 1));
        }
        return out;
    }

    /** The same study's placebo group: every remission ended in a relapse. */
    static List<KaplanMeier.Observation> placebo() {
        double[] t = {1, 1, 2, 2, 3, 4, 4, 5, 5, 8, 8, 8, 8, 11, 11, 12, 12, 15, 17, 22, 23};
        List<KaplanMeier.Observation> out = new ArrayList<>();
        for (double x : t) {
            out.add(new KaplanMeier.Observation(x, true));
        }
        return out;
    }

    @Test
    void theSixMpCurveIsTheTextbookOne() {
        // the textbook values (e.g. Kleinbaum & Klein), also what Python's lifelines 0.30 gives on the same data
        List<KaplanMeier.Step> curve = KaplanMeier.curve(sixMp());
        double[][] expected = {{6, 21, 3, 0.857143}, {7, 17, 1, 0.806723}, {10, 15, 1, 0.752941},
            {13, 12, 1, 0.690196}, {16, 11, 1, 0.627451}, {22, 7, 1, 0.537815}, {23, 6, 1, 0.448179}};
        assertEquals(expected.length, curve.size());
        for (int i = 0; i < expected.length; i++) {
            KaplanMeier.Step s = curve.get(i);
            assertEquals(expected[i][0], s.time());
            assertEquals((int) expected[i][1], s.atRisk(), "at risk at " + s.time());
            assertEquals((int) expected[i][2], s.events());
            assertEquals(expected[i][3], s.survival(), 1e-6);
        }
        assertEquals(23, KaplanMeier.median(curve).orElseThrow());
        assertEquals(0.806723, KaplanMeier.survivalAt(curve, 9), 1e-6, "a censored time does not drop the curve");
        assertEquals(1, KaplanMeier.survivalAt(curve, 5.9));
    }

    @Test
    void aCurveThatNeverFallsToOneHalfHasNoMedian() {
        List<KaplanMeier.Observation> mostlyCensored = List.of(new KaplanMeier.Observation(3, true),
                new KaplanMeier.Observation(10, false), new KaplanMeier.Observation(10, false),
                new KaplanMeier.Observation(10, false));
        List<KaplanMeier.Step> curve = KaplanMeier.curve(mostlyCensored);
        assertEquals(0.75, curve.get(0).survival(), 1e-12);
        assertTrue(KaplanMeier.median(curve).isEmpty());
        assertTrue(KaplanMeier.curve(List.of(new KaplanMeier.Observation(5, false))).isEmpty());
    }

    private static List<KaplanMeier.Observation> observations(double[] times, boolean[] events) {
        List<KaplanMeier.Observation> out = new ArrayList<>();
        for (int i = 0; i < times.length; i++) {
            out.add(new KaplanMeier.Observation(times[i], events[i]));
        }
        return out;
    }

    @Test
    void theMedianIntervalOfFiveEventsSpansTheirFirstToTheirLast() {
        // S = 0.8, 0.6, 0.4, 0.2, 0 at 1..5; Greenwood sums 1/20, +1/12, +1/6, +1/2, then S = 0 (se 0).
        // At t = 1: se = 0.8 * sqrt(0.05) = 0.1789, S - 1.96 se = 0.449 <= 0.5: the lower end is 1.
        // S + 1.96 se: 1.151, 1.029, 0.829, 0.551 at 1..4, and 0 at 5: the upper end is 5. The median is 3.
        List<KaplanMeier.Step> curve = KaplanMeier.curve(observations(new double[] {1, 2, 3, 4, 5},
                new boolean[] {true, true, true, true, true}));
        KaplanMeier.MedianInterval ci = KaplanMeier.medianInterval(curve, 1.959964);
        assertEquals(3, KaplanMeier.median(curve).getAsDouble(), 1e-12);
        assertEquals(1, ci.low().getAsDouble(), 1e-12);
        assertEquals(5, ci.high().getAsDouble(), 1e-12);
    }

    @Test
    void theMedianIntervalWithCensoredTimesFollowsGreenwoodsVariance() {
        // 2, 3+, 4, 5+, 6, 7 (+ censored). S(2) = 5/6, Greenwood 1/30: se 0.1521, S - 1.96 se = 0.535 > 0.5.
        // S(4) = 5/6 * 3/4 = 0.625, Greenwood 1/30 + 1/12 = 0.1167: se 0.2135, S - 1.96 se = 0.207: the lower end is 4.
        // S(6) = 0.3125 (the median), Greenwood + 1/2 = 0.6167: se 0.2454, S + 1.96 se = 0.794 > 0.5.
        // S(7) = 0, se 0: the upper end is 7.
        List<KaplanMeier.Step> curve = KaplanMeier.curve(observations(new double[] {2, 3, 4, 5, 6, 7},
                new boolean[] {true, false, true, false, true, true}));
        KaplanMeier.MedianInterval ci = KaplanMeier.medianInterval(curve, 1.959964);
        assertEquals(6, KaplanMeier.median(curve).getAsDouble(), 1e-12);
        assertEquals(4, ci.low().getAsDouble(), 1e-12);
        assertEquals(7, ci.high().getAsDouble(), 1e-12);
    }

    @Test
    void anIntervalEndThatItsBandNeverReachesIsNotReached() {
        // 1 event in 4, the rest censored: S = 0.75 with se 0.2165, S - 1.96 se = 0.326 <= 0.5, S + 1.96 se never is
        List<KaplanMeier.Step> curve = KaplanMeier.curve(observations(new double[] {1, 9, 9, 9},
                new boolean[] {true, false, false, false}));
        KaplanMeier.MedianInterval ci = KaplanMeier.medianInterval(curve, 1.959964);
        assertTrue(KaplanMeier.median(curve).isEmpty());
        assertEquals(1, ci.low().getAsDouble(), 1e-12);
        assertTrue(ci.high().isEmpty());
    }
}
