package sitcov.world;

import java.util.Arrays;
import java.util.EnumMap;
import java.util.Map;

/**
 * A proposal distribution for the generator: for some {@link DrawSite}s a probability per bin in
 * place of the generator's equal ones; every other draw keeps the generator's law, so it cancels
 * from a map's likelihood ratio. Immutable.
 */
public final class Tilt {
    /** The generator itself: no site tilted. */
    public static final Tilt NOMINAL = new Tilt(new EnumMap<>(DrawSite.class));

    private final Map<DrawSite, double[]> probabilities;

    private Tilt(Map<DrawSite, double[]> probabilities) {
        this.probabilities = probabilities;
    }

    /**
     * A tilt giving each named site the bin probabilities listed (normalised here).
     *
     * @throws IllegalArgumentException when a list has the wrong length, a negative or non-finite
     *                                  entry, or no positive one
     */
    public static Tilt of(Map<DrawSite, double[]> probabilities) {
        Map<DrawSite, double[]> kept = new EnumMap<>(DrawSite.class);
        for (Map.Entry<DrawSite, double[]> e : probabilities.entrySet()) {
            DrawSite site = e.getKey();
            double[] p = e.getValue();
            if (p.length != site.bins()) {
                throw new IllegalArgumentException(site.key() + " has " + site.bins() + " bins, not " + p.length);
            }
            double sum = 0;
            for (double v : p) {
                if (!(v >= 0) || Double.isInfinite(v)) {
                    throw new IllegalArgumentException(site.key() + ": a bin's probability must be finite and >= 0, not " + v);
                }
                sum += v;
            }
            if (!(sum > 0)) {
                throw new IllegalArgumentException(site.key() + ": some bin needs a positive probability");
            }
            double[] normalised = new double[p.length];
            for (int b = 0; b < p.length; b++) {
                normalised[b] = p[b] / sum;
            }
            kept.put(site, normalised);
        }
        return new Tilt(kept);
    }

    public boolean tilts(DrawSite site) {
        return probabilities.containsKey(site);
    }

    /** The proposal's probability of bin {@code bin} of {@code site}: the generator's 1/bins where untilted. */
    public double probability(DrawSite site, int bin) {
        double[] p = probabilities.get(site);
        return p == null ? 1.0 / site.bins() : p[bin];
    }

    /** The bin whose cumulative probability first exceeds {@code u}: inverse-CDF sampling of the site's bins. */
    int bin(DrawSite site, double u) {
        double[] p = probabilities.get(site);
        double below = 0;
        for (int b = 0; b < p.length - 1; b++) {
            below += p[b];
            if (u < below) {
                return b;
            }
        }
        return p.length - 1;
    }

    /** The cumulative probability below bin {@code bin}, summed as {@link #bin} sums it. */
    double below(DrawSite site, int bin) {
        double[] p = probabilities.get(site);
        double below = 0;
        for (int b = 0; b < bin; b++) {
            below += p[b];
        }
        return below;
    }

    @Override
    public boolean equals(Object o) {
        if (!(o instanceof Tilt t) || !t.probabilities.keySet().equals(probabilities.keySet())) {
            return false;
        }
        return probabilities.entrySet().stream().allMatch(e -> Arrays.equals(e.getValue(), t.probabilities.get(e.getKey())));
    }

    @Override
    public int hashCode() {
        return probabilities.keySet().hashCode();
    }
}
