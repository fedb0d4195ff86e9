package sitcov.stats;

import java.util.List;
import java.util.TreeSet;

/**
 * The log-rank test of two survival curves (Mantel–Haenszel): at each distinct event time, the
 * events of group A are compared with what A's share of the risk set would expect, and the
 * differences are summed over time; (O − E)² / V is chi-square with one degree of freedom under
 * equal curves. Censored trials count in the risk set up to their time.
 */
public final class LogRank {
    private LogRank() {
    }

    /**
     * @param observedA events in group A
     * @param expectedA events A would have had if both groups shared one curve
     * @param variance  the hypergeometric variance of A's events, summed over event times
     * @param chiSquare (O − E)² / V; 0 when no time had an event
     * @param p         two-sided p-value, chi-square with one degree of freedom (1 when V is 0)
     */
    public record Result(double observedA, double expectedA, double variance, double chiSquare, double p) {
    }

    public static Result test(List<KaplanMeier.Observation> a, List<KaplanMeier.Observation> b) {
        TreeSet<Double> eventTimes = new TreeSet<>();
        for (List<KaplanMeier.Observation> group : List.of(a, b)) {
            for (KaplanMeier.Observation o : group) {
                if (o.event()) {
                    eventTimes.add(o.time());
                }
            }
        }
        double observed = 0;
        double expected = 0;
        double variance = 0;
        for (double t : eventTimes) {
            int nA = atRisk(a, t);
            int nB = atRisk(b, t);
            int dA = events(a, t);
            int d = dA + events(b, t);
            int n = nA + nB;
            observed += dA;
            expected += (double) d * nA / n;
            if (n > 1) {
                variance += (double) d * nA * nB * (n - d) / ((double) n * n * (n - 1));
            }
        }
        if (variance == 0) {
            return new Result(observed, expected, 0, 0, 1);
        }
        double chi = (observed - expected) * (observed - expected) / variance;
        // chi-square with one degree of freedom is a squared standard normal: both tails of |Z| > √χ²
        return new Result(observed, expected, variance, chi, 2 * Normal.upperTail(Math.sqrt(chi)));
    }

    private static int atRisk(List<KaplanMeier.Observation> group, double t) {
        int n = 0;
        for (KaplanMeier.Observation o : group) {
            if (o.time() >= t) {
                n++;
            }
        }
        return n;
    }

    private static int events(List<KaplanMeier.Observation> group, double t) {
        int d = 0;
        for (KaplanMeier.Observation o : group) {
            if (o.event() && o.time() == t) {
                d++;
            }
        }
        return d;
    }
}
