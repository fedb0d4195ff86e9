package sitcov.stats;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import org.junit.jupiter.api.Test;

class PairedLogRankTest {
    private static KaplanMeier.Observation event(double t) {
        return new KaplanMeier.Observation(t, true);
    }

    private static KaplanMeier.Observation censored(double t) {
        return new KaplanMeier.Observation(t, false);
    }

    @Test
    void eachPairAddsHalfToTheOneThatFellFirstAndAQuarterToTheVariance() {
        List<KaplanMeier.Observation> a = List.of(event(10), event(30), censored(100), censored(100), event(40), event(60),
                event(70), event(90));
        List<KaplanMeier.Observation> b = List.of(event(20), censored(100), event(50), censored(100), event(40),
                censored(50), event(80), censored(90));
        PairedLogRank.Result r = PairedLogRank.test(a, b);
        // A first in pairs 1, 2, 7 and 8 (B censored at A's event time is still at risk), B first in pair 3;
        // pair 4 has no event, pair 5 ties (d = 2, V = 0), in pair 6 B was censored before A fell (A alone at risk)
        assertEquals(4, r.firstA());
        assertEquals(1, r.firstB());
        // O: A's 6 events; E: 0.5 in each of the 5 informative pairs, 1 for the tie, 1 for A alone: 4.5
        assertEquals(6, r.observedA(), 1e-12);
        assertEquals(4.5, r.expectedA(), 1e-12);
        assertEquals(5 * 0.25, r.variance(), 1e-12);
        // (O - E)^2 / V = 2.25 / 1.25 = (4 - 1)^2 / 5: the sign test's statistic; its exact p is 2 (1 + 5) / 32
        assertEquals(0.375, r.p(), 1e-12);
    }
}
