package sitcov.stats;

/**
 * Student's t distribution with ν degrees of freedom, for the paired t intervals behind the
 * equivalence tests ({@link Tost}) and the smallest detectable difference ({@link DetectableDifference}).
 *
 * <p>The distribution function is written through the regularized incomplete beta function: for
 * t ≥ 0, P(T ≤ t) = 1 − ½·I_x(ν/2, ½) with x = ν/(ν + t²) (Abramowitz &amp; Stegun 1964, 26.5.27 and
 * 26.7.1). I_x(a, b) is summed as the continued fraction of A&amp;S 26.5.8 by the modified Lentz
 * method, on the side of x where it converges fast, with ln Γ from Lanczos' approximation (g = 7,
 * nine coefficients, about 15 significant digits). The quantile is the root of the distribution
 * function, found by bisection to the last bit: no hot path uses it.
 */
public final class StudentT {
    private static final double[] LANCZOS = {0.99999999999980993, 676.5203681218851, -1259.1392167224028,
        771.32342877765313, -176.61502916214059, 12.507343278686905, -0.13857109526572012,
        9.9843695780195716e-6, 1.5056327351493116e-7};
    private static final int MAX_TERMS = 10_000;
    private static final double EPSILON = 1e-16;
    private static final double TINY = 1e-300;

    private StudentT() {
    }

    /** P(T ≤ t) for T with {@code df} degrees of freedom. */
    public static double cdf(double t, double df) {
        if (!(df > 0)) {
            throw new IllegalArgumentException("degrees of freedom must be positive: " + df);
        }
        if (Double.isNaN(t)) {
            return Double.NaN;
        }
        if (Double.isInfinite(t)) {
            return t > 0 ? 1 : 0;
        }
        double tail = 0.5 * regularizedBeta(df / (df + t * t), df / 2, 0.5);
        return t > 0 ? 1 - tail : tail;
    }

    /** The t with P(T ≤ t) = {@code p}. */
    public static double quantile(double p, double df) {
        if (!(p > 0 && p < 1)) {
            throw new IllegalArgumentException("a quantile needs 0 < p < 1: " + p);
        }
        double low = -1;
        double high = 1;
        while (cdf(low, df) > p) {
            low *= 2;
        }
        while (cdf(high, df) < p) {
            high *= 2;
        }
        for (int i = 0; i < 200 && high - low > Math.ulp(Math.max(Math.abs(low), Math.abs(high))); i++) {
            double mid = 0.5 * (low + high);
            if (cdf(mid, df) < p) {
                low = mid;
            } else {
                high = mid;
            }
        }
        return 0.5 * (low + high);
    }

    /** I_x(a, b), the regularized incomplete beta function. */
    static double regularizedBeta(double x, double a, double b) {
        if (x <= 0) {
            return 0;
        }
        if (x >= 1) {
            return 1;
        }
        double front = Math.exp(a * Math.log(x) + b * Math.log1p(-x) + logGamma(a + b) - logGamma(a) - logGamma(b));
        // the fraction converges fast for x < (a + 1) / (a + b + 2); beyond, I_x(a, b) = 1 − I_{1−x}(b, a)
        if (x < (a + 1) / (a + b + 2)) {
            return front * fraction(x, a, b) / a;
        }
        return 1 - front * fraction(1 - x, b, a) / b;
    }

    /** The continued fraction of A&amp;S 26.5.8, by the modified Lentz method. */
    private static double fraction(double x, double a, double b) {
        double c = 1;
        double d = nonZero(1 - (a + b) * x / (a + 1));
        d = 1 / d;
        double h = d;
        for (int m = 1; m <= MAX_TERMS; m++) {
            int m2 = 2 * m;
            double even = m * (b - m) * x / ((a + m2 - 1) * (a + m2));
            d = 1 / nonZero(1 + even * d);
            c = nonZero(1 + even / c);
            h *= d * c;
            double odd = -(a + m) * (a + b + m) * x / ((a + m2) * (a + m2 + 1));
            d = 1 / nonZero(1 + odd * d);
            c = nonZero(1 + odd / c);
            double step = d * c;
            h *= step;
            if (Math.abs(step - 1) < EPSILON) {
                return h;
            }
        }
        throw new ArithmeticException("the incomplete beta fraction did not converge for x=" + x + ", a=" + a + ", b=" + b);
    }

    private static double nonZero(double v) {
        return Math.abs(v) < TINY ? TINY : v;
    }

    /** ln Γ(x) for x &gt; 0, Lanczos' approximation (with the reflection formula below ½). */
    static double logGamma(double x) {
        if (x < 0.5) {
            return Math.log(Math.PI / Math.abs(Math.sin(Math.PI * x))) - logGamma(1 - x);
        }
        double z = x - 1;
        double sum = LANCZOS[0];
        double t = z + 7.5;
        for (int i = 1; i < LANCZOS.length; i++) {
            sum += LANCZOS[i] / (z + i);
        }
        return 0.5 * Math.log(2 * Math.PI) + (z + 0.5) * Math.log(t) - t + Math.log(sum);
    }
}
