package sitcov.stats;

/**
 * McNemar's exact test for paired binary outcomes (McNemar 1947, Psychometrika 12:153; the exact
 * form is the binomial test on the discordant pairs). Of the pairs where the two differ, {@code b}
 * went one way and {@code c} the other; under the null hypothesis each discordant pair goes either
 * way with probability ½, so the two-sided p is 2·P(X ≤ min(b, c)) for X ~ Binomial(b + c, ½),
 * capped at 1. With no discordant pair there is nothing to test and p is 1.
 */
public final class McNemar {
    private McNemar() {
    }

    /**
     * The smallest two-sided p any split of {@code discordant} pairs can give: 2·½ⁿ (all one way), capped at
     * 1. Below 6 discordant pairs it is above 0.05 (0.0625 for 5), so such a test cannot show a difference.
     */
    public static double smallestP(long discordant) {
        return exactP(discordant, 0);
    }

    public static double exactP(long b, long c) {
        if (b < 0 || c < 0) {
            throw new IllegalArgumentException("counts of discordant pairs are not negative, got " + b + " and " + c);
        }
        long n = b + c;
        if (n == 0) {
            return 1;
        }
        long k = Math.min(b, c);
        double tail = 0;
        for (long i = 0; i <= k; i++) {
            tail += Math.exp(LogFactorial.of(n) - LogFactorial.of(i) - LogFactorial.of(n - i) - n * Math.log(2));
        }
        return Math.min(1, 2 * tail);
    }
}
