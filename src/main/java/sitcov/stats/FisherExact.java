package sitcov.stats;

/**
 * Fisher's exact test of independence in a 2×2 table, with the sample odds ratio and its Woolf
 * interval: do, say, two configurations find a fault in different proportions of their runs?
 *
 * <p>The table is
 * <pre>
 *   a  b
 *   c  d
 * </pre>
 * With all margins fixed, a follows the hypergeometric distribution (Fisher 1935, The Design of
 * Experiments, §2; Agresti, Categorical Data Analysis, 2nd ed. 2002, §3.5.1). The two-sided p-value
 * sums the probabilities of every table with these margins that is no more probable than the one
 * observed, the probabilities compared with a relative tolerance of 1e−7 so that tables equally
 * likely in exact arithmetic are not lost to rounding, exactly as R's {@code fisher.test} does.
 * Probabilities are formed from ln n! ({@link LogFactorial}) and scaled by the most likely table
 * before exponentiating, so large tables neither overflow nor underflow.
 *
 * <p>The odds ratio is the sample (unconditional) estimate ad/(bc), not the conditional maximum
 * likelihood estimate R's {@code fisher.test} reports, and its 95 % interval is Woolf's logit
 * interval exp(ln OR ± z·√(1/a + 1/b + 1/c + 1/d)) (Woolf 1955, Annals of Human Genetics 19:251;
 * Bland &amp; Altman 2000, BMJ 320:1468). When a cell is zero that interval is undefined, so the
 * Haldane–Anscombe correction adds ½ to every cell (Haldane 1956, Annals of Human Genetics 20:309;
 * Anscombe 1956, Biometrika 43:461) for both the estimate and its interval, and the result says so.
 */
public final class FisherExact {
    /** R's {@code fisher.test} tolerance: tables within this relative margin count as equally likely. */
    private static final double RELATIVE_TOLERANCE = 1e-7;

    private FisherExact() {
    }

    /**
     * The outcome of a test.
     *
     * @param p the two-sided exact p-value
     * @param oddsRatio ad/(bc), after the Haldane–Anscombe correction when {@code corrected}
     * @param low lower end of the Woolf interval for the odds ratio
     * @param high upper end of the Woolf interval for the odds ratio
     * @param corrected whether ½ was added to every cell because one of them was zero
     */
    public record Result(double p, double oddsRatio, double low, double high, boolean corrected) {
    }

    /** Tests the table [[a, b], [c, d]] with a 95 % interval for the odds ratio. */
    public static Result test(long a, long b, long c, long d) {
        return test(a, b, c, d, 0.95);
    }

    /** Tests the table [[a, b], [c, d]] with an interval of the given {@code confidence} in (0, 1). */
    public static Result test(long a, long b, long c, long d, double confidence) {
        if (a < 0 || b < 0 || c < 0 || d < 0) {
            throw new IllegalArgumentException("counts must be non-negative");
        }
        if (!(confidence > 0 && confidence < 1)) {
            throw new IllegalArgumentException("confidence must be in (0, 1): " + confidence);
        }
        boolean corrected = a == 0 || b == 0 || c == 0 || d == 0;
        double shift = corrected ? 0.5 : 0;
        double ca = a + shift;
        double cb = b + shift;
        double cc = c + shift;
        double cd = d + shift;
        double logOdds = Math.log(ca) + Math.log(cd) - Math.log(cb) - Math.log(cc);
        double z = Normal.quantile(0.5 + confidence / 2);
        double halfWidth = z * Math.sqrt(1 / ca + 1 / cb + 1 / cc + 1 / cd);
        return new Result(twoSidedP(a, b, c, d), Math.exp(logOdds), Math.exp(logOdds - halfWidth),
            Math.exp(logOdds + halfWidth), corrected);
    }

    /** Fisher's two-sided p-value of the table [[a, b], [c, d]]. */
    public static double twoSidedP(long a, long b, long c, long d) {
        long row1 = a + b;
        long row2 = c + d;
        long col1 = a + c;
        long n = row1 + row2;
        long lo = Math.max(0, col1 - row2);
        long hi = Math.min(row1, col1);
        double[] logP = new double[(int) (hi - lo + 1)];
        double max = Double.NEGATIVE_INFINITY;
        for (long x = lo; x <= hi; x++) {
            // The margins' part of ln P is the same for every table, so only the cells' part is kept.
            double l = -(LogFactorial.of(x) + LogFactorial.of(row1 - x) + LogFactorial.of(col1 - x)
                + LogFactorial.of(n - row1 - col1 + x));
            logP[(int) (x - lo)] = l;
            max = Math.max(max, l);
        }
        double observed = Math.exp(logP[(int) (a - lo)] - max);
        double total = 0;
        double asExtreme = 0;
        for (double l : logP) {
            double p = Math.exp(l - max);
            total += p;
            if (p <= observed * (1 + RELATIVE_TOLERANCE)) {
                asExtreme += p;
            }
        }
        return Math.min(1, asExtreme / total);
    }
}
