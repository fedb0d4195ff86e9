package sitcov.stats;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import org.junit.jupiter.api.Test;

class LogRankTest {
    @Test
    void sixMpAgainstPlaceboGivesTheTextbookChiSquare() {
        // Freireich et al. (1963): chi-square 16.79 on 1 df, p = 4.17e-5 (R's survdiff; lifelines 0.30 gives
        // 16.7929409892 and p 4.16880910933e-05 on the same data)
        LogRank.Result r = LogRank.test(KaplanMeierTest.sixMp(), KaplanMeierTest.placebo());
        assertEquals(9, r.observedA(), 1e-12);
        assertEquals(19.2505, r.expectedA(), 1e-4);
        assertEquals(16.7929409892, r.chiSquare(), 1e-8);
        assertEquals(4.16880910933e-05, r.p(), 1e-9);
    }

    @Test
    void theTestIsSymmetricInItsGroups() {
        LogRank.Result ab = LogRank.test(KaplanMeierTest.sixMp(), KaplanMeierTest.placebo());
        LogRank.Result ba = LogRank.test(KaplanMeierTest.placebo(), KaplanMeierTest.sixMp());
        assertEquals(ab.chiSquare(), ba.chiSquare(), 1e-9);
        assertEquals(ab.p(), ba.p(), 1e-12);
    }

    @Test
    void groupsWithoutAnyEventShowNoDifference() {
        List<KaplanMeier.Observation> censored = List.of(new KaplanMeier.Observation(10, false));
        LogRank.Result r = LogRank.test(censored, censored);
        assertEquals(0, r.chiSquare());
        assertEquals(1, r.p());
    }
}
