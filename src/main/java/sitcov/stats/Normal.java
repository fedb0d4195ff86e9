package sitcov.stats;

/**
 * The standard normal distribution, which the large-sample approximations of the rank tests, the
 * Wilson interval and Woolf's odds-ratio interval all lean on. The JDK has no {@code erf}, so both
 * directions are written here.
 *
 * <p>{@link #cdf} is W. J. Cody's rational Chebyshev approximation (Cody 1969, "Rational Chebyshev
 * approximations for the error function", Mathematics of Computation 23:631; routine ANORM of
 * the special-function package of ACM TOMS Algorithm 715, 1993), the same one R's {@code pnorm}
 * uses: near double precision, and the lower tail is computed directly, so Φ(−10) ≈ 7.6e−24 keeps its relative accuracy instead
 * of vanishing in {@code 1 − Φ(10)}.
 *
 * <p>{@link #quantile} is P. J. Acklam's rational approximation (Acklam 2003, "An algorithm for
 * computing the inverse normal cumulative distribution function", relative error 1.15e−9), refined
 * by one Halley step on {@link #cdf} as Acklam suggests, which brings it to about machine precision.
 */
public final class Normal {
    private static final double SQRT_2PI = Math.sqrt(2 * Math.PI);
    private static final double INV_SQRT_2PI = 1 / SQRT_2PI;

    // Cody's coefficients: |x| <= 0.67448975 (a, b), up to sqrt(32) (c, d), beyond (p, q).
    private static final double[] A = {2.2352520354606839287, 161.02823106855587881, 1067.6894854603709582,
        18154.981253343561249, 0.065682337918207449113};
    private static final double[] B = {47.20258190468824187, 976.09855173777669322, 10260.932208618978205,
        45507.789335026729956};
    private static final double[] C = {0.39894151208813466764, 8.8831497943883759412, 93.506656132177855979,
        597.27027639480026226, 2494.5375852903726711, 6848.1904505362823326, 11602.651437647350124,
        9842.7148383839780218, 1.0765576773720192317e-8};
    private static final double[] D = {22.266688044328115691, 235.38790178262499861, 1519.377599407554805,
        6485.558298266760755, 18615.571640885098091, 34900.952721145977266, 38912.003286093271411,
        19685.429676859990727};
    private static final double[] P = {0.21589853405795699, 0.1274011611602473639, 0.022235277870649807,
        0.001421619193227893466, 2.9112874951168792e-5, 0.02307344176494017303};
    private static final double[] Q = {1.28426009614491121, 0.468238212480865118, 0.0659881378689285515,
        0.00378239633202758244, 7.29751555083966205e-5};

    // Acklam's coefficients: central region (a, b) and tails below P_LOW (c, d).
    private static final double[] AA = {-3.969683028665376e+01, 2.209460984245205e+02, -2.759285104469687e+02,
        1.383577518672690e+02, -3.066479806614716e+01, 2.506628277459239e+00};
    private static final double[] AB = {-5.447609879822406e+01, 1.615858368580409e+02, -1.556989798598866e+02,
        6.680131188771972e+01, -1.328068155288572e+01};
    private static final double[] AC = {-7.784894002430293e-03, -3.223964580411365e-01, -2.400758277161838e+00,
        -2.549732539343734e+00, 4.374664141464968e+00, 2.938163982698783e+00};
    private static final double[] AD = {7.784695709041462e-03, 3.224671290700398e-01, 2.445134137142996e+00,
        3.754408661907416e+00};
    private static final double P_LOW = 0.02425;

    private Normal() {
    }

    /** Φ(x) = P(Z ≤ x) for a standard normal Z. */
    public static double cdf(double x) {
        if (Double.isNaN(x)) {
            return Double.NaN;
        }
        double y = Math.abs(x);
        if (y <= 0.67448975) {
            double xsq = x * x;
            double num = A[4] * xsq;
            double den = xsq;
            for (int i = 0; i < 3; i++) {
                num = (num + A[i]) * xsq;
                den = (den + B[i]) * xsq;
            }
            return 0.5 + x * (num + A[3]) / (den + B[3]);
        }
        double tail = smallerTail(y);
        return x > 0 ? 1 - tail : tail;
    }

    /** P(Z > x), accurate in the far upper tail where {@code 1 - cdf(x)} would cancel to zero. */
    public static double upperTail(double x) {
        return cdf(-x);
    }

    /** Φ(−y) for y > 0.674: Cody's two outer ranges. */
    private static double smallerTail(double y) {
        double ratio;
        if (y <= Math.sqrt(32)) {
            double num = C[8] * y;
            double den = y;
            for (int i = 0; i < 7; i++) {
                num = (num + C[i]) * y;
                den = (den + D[i]) * y;
            }
            ratio = (num + C[7]) / (den + D[7]);
        } else if (y < 37.5193) {
            double inv = 1 / (y * y);
            double num = P[5] * inv;
            double den = inv;
            for (int i = 0; i < 4; i++) {
                num = (num + P[i]) * inv;
                den = (den + Q[i]) * inv;
            }
            ratio = (INV_SQRT_2PI - inv * (num + P[4]) / (den + Q[4])) / y;
        } else {
            return 0;
        }
        // exp(-y^2/2) split as Cody does: y rounded to 1/16 squares exactly, the rest is small.
        double rounded = Math.floor(y * 16) / 16;
        double del = (y - rounded) * (y + rounded);
        return Math.exp(-rounded * rounded * 0.5) * Math.exp(-del * 0.5) * ratio;
    }

    /** The standard normal density φ(x). */
    public static double density(double x) {
        return INV_SQRT_2PI * Math.exp(-0.5 * x * x);
    }

    /** Φ⁻¹(p): the z with Φ(z) = p; −∞ at 0 and +∞ at 1. */
    public static double quantile(double p) {
        if (Double.isNaN(p) || p < 0 || p > 1) {
            throw new IllegalArgumentException("probability must be in [0, 1]: " + p);
        }
        if (p == 0) {
            return Double.NEGATIVE_INFINITY;
        }
        if (p == 1) {
            return Double.POSITIVE_INFINITY;
        }
        if (p > 0.5) {
            return -quantile(1 - p); // 1 - p is exact for p in [0.5, 1]; the lower tail is the accurate one
        }
        double x;
        if (p < P_LOW) {
            double q = Math.sqrt(-2 * Math.log(p));
            x = (((((AC[0] * q + AC[1]) * q + AC[2]) * q + AC[3]) * q + AC[4]) * q + AC[5])
                / ((((AD[0] * q + AD[1]) * q + AD[2]) * q + AD[3]) * q + 1);
        } else {
            double q = p - 0.5;
            double r = q * q;
            x = (((((AA[0] * r + AA[1]) * r + AA[2]) * r + AA[3]) * r + AA[4]) * r + AA[5]) * q
                / (((((AB[0] * r + AB[1]) * r + AB[2]) * r + AB[3]) * r + AB[4]) * r + 1);
        }
        // One Halley step on Φ(x) - p (Acklam's refinement).
        double c = cdf(x);
        if (c == 0) {
            return x; // p below ~1e-308, where cdf underflows: Acklam's own 1e-9 is all there is
        }
        double u = (c - p) * SQRT_2PI * Math.exp(x * x / 2);
        return x - u / (1 + x * u / 2);
    }
}
