package sitcov.stats;

/**
 * How many kinds not yet seen a larger sample would find, from the counts of kinds seen once and
 * twice: Chao's species-accumulation extrapolation (Chao et al. 2014, Ecological Monographs 84:45,
 * eq. 9, with the bias-corrected Chao1 estimate of the unseen kinds). A coverage driver that runs a
 * map only for a new cell uses it to foresee how many maps its remaining candidates will bring.
 */
public final class Richness {
    private Richness() {
    }

    /** Chao1's bias-corrected estimate of the kinds not seen in a sample of {@code n} with {@code f1} singletons and {@code f2} doubletons. */
    public static double unseen(long n, long f1, long f2) {
        if (n <= 1 || f1 == 0) {
            return 0;
        }
        double shrink = (n - 1) / (double) n;
        return f2 > 0 ? shrink * f1 * f1 / (2.0 * f2) : shrink * f1 * (f1 - 1) / 2.0;
    }

    /** The expected number of new kinds in {@code m} more draws after a sample of {@code n}. */
    public static double expectedNew(long n, long f1, long f2, long m) {
        double f0 = unseen(n, f1, f2);
        if (f0 <= 0 || m <= 0) {
            return 0;
        }
        return f0 * (1 - Math.pow(1 - f1 / (n * f0 + f1), m));
    }
}
