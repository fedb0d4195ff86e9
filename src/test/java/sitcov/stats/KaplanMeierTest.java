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
}
