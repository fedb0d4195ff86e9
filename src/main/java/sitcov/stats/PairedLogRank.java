package sitcov.stats;

import java.util.List;

/**
 * The log-rank test stratified by pair, for two survival times observed in pairs (a campaign's two drivers
 * reading one trial's candidate stream): each pair is a stratum, its observed and expected events of A and
 * their variance ({@link LogRank}) summed over the pairs. In a stratum of two, only the first event can
 * inform, and only when the other is still at risk then: it adds ½ to O − E for the one that fell first
 * (−½ for the other) and ¼ to V; ties, pairs with no event and pairs whose other member was censored
 * earlier add nothing. So (ΣO − ΣE)²/ΣV is (a − b)²/(a + b), a the pairs in which A fell first and b those in
 * which B did: the sign test's statistic. Its p is the sign test's exact binomial p (as {@link McNemar}'s),
 * which holds for few pairs where the chi-square approximation does not.
 */
public final class PairedLogRank {
    private PairedLogRank() {
    }

    /**
     * @param observedA ΣO of A, the events of A over the pairs
     * @param expectedA ΣE of A
     * @param variance  ΣV
     * @param firstA    pairs in which A had the event first, B still at risk
     * @param firstB    pairs in which B had it first, A still at risk
     * @param p         the exact two-sided p of the sign test on {@code firstA} against {@code firstB}
     */
    public record Result(double observedA, double expectedA, double variance, int firstA, int firstB, double p) {
        /** Pairs whose first event tells the two apart. */
        public int informative() {
            return firstA + firstB;
        }
    }

    /** {@code a.get(i)} and {@code b.get(i)} are pair i. */
    public static Result test(List<KaplanMeier.Observation> a, List<KaplanMeier.Observation> b) {
        if (a.size() != b.size()) {
            throw new IllegalArgumentException("pairs need as many observations of A as of B, got " + a.size() + " and "
                    + b.size());
        }
        double o = 0;
        double e = 0;
        double v = 0;
        int firstA = 0;
        int firstB = 0;
        for (int i = 0; i < a.size(); i++) {
            LogRank.Result r = LogRank.test(List.of(a.get(i)), List.of(b.get(i)));
            o += r.observedA();
            e += r.expectedA();
            v += r.variance();
            if (r.variance() > 0) {
                if (r.observedA() > r.expectedA()) {
                    firstA++;
                } else {
                    firstB++;
                }
            }
        }
        return new Result(o, e, v, firstA, firstB, McNemar.exactP(firstA, firstB));
    }
}
