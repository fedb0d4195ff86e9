package sitcov.stats;

/**
 * ln(n!) without overflow, for the hypergeometric probabilities of Fisher's exact test. Small n are
 * summed once into a table (exact to rounding); larger n use Stirling's series
 * ln n! = n ln n − n + ½ ln(2πn) + 1/(12n) − 1/(360n³) + 1/(1260n⁵) (Abramowitz &amp; Stegun 1964,
 * 6.1.41), whose next term, 1/(1680n⁷), is below 1e−24 beyond the table.
 */
final class LogFactorial {
    private static final int TABLE_SIZE = 1024;
    private static final double[] TABLE = new double[TABLE_SIZE];

    static {
        for (int i = 1; i < TABLE_SIZE; i++) {
            TABLE[i] = TABLE[i - 1] + Math.log(i);
        }
    }

    private LogFactorial() {
    }

    static double of(long n) {
        if (n < 0) {
            throw new IllegalArgumentException("factorial of a negative number: " + n);
        }
        if (n < TABLE_SIZE) {
            return TABLE[(int) n];
        }
        double x = n;
        double inv = 1 / x;
        double inv2 = inv * inv;
        return x * Math.log(x) - x + 0.5 * Math.log(2 * Math.PI * x)
            + inv * (1.0 / 12 - inv2 * (1.0 / 360 - inv2 / 1260));
    }
}
