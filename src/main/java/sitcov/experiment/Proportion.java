package sitcov.experiment;

/** A share of successes among trials, with its 95% Wilson score interval. */
public record Proportion(long successes, long trials) {
    private static final double Z95 = 1.959963984540054;

    public Proportion {
        if (trials < 0 || successes < 0 || successes > trials) {
            throw new IllegalArgumentException("a proportion needs 0 <= successes <= trials, got " + successes + "/" + trials);
        }
    }

    public double share() {
        return trials == 0 ? 0 : (double) successes / trials;
    }

    public double wilsonLow() {
        return wilson(-1);
    }

    public double wilsonHigh() {
        return wilson(1);
    }

    private double wilson(int side) {
        if (trials == 0) {
            return side < 0 ? 0 : 1;
        }
        double n = trials;
        double p = share();
        double z2 = Z95 * Z95;
        double centre = p + z2 / (2 * n);
        double spread = Z95 * Math.sqrt(p * (1 - p) / n + z2 / (4 * n * n));
        double bound = (centre + side * spread) / (1 + z2 / n);
        return Math.max(0, Math.min(1, bound));
    }
}
