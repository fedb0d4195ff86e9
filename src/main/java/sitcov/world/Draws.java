package sitcov.world;

import java.util.random.RandomGenerator;

/**
 * The generator's key draws ({@link DrawSite}), made under a {@link Tilt} and traced: each draw's
 * bin, and the log-likelihood of the draws under the generator and under the tilt. Every draw takes
 * exactly one number from the stream it is given, tilted or not, so a tilt changes which map a seed
 * gives but not how the generator's other draws line up; untilted, a draw is the number the
 * generator always drew, so {@link MapGenerator#generate(long)} is unchanged. One per map.
 */
public final class Draws {
    private final Tilt tilt;
    private final int[][] bins = new int[DrawSite.values().length][];
    private double logNominal;
    private double logProposal;

    public Draws(Tilt tilt) {
        this.tilt = tilt;
        for (DrawSite s : DrawSite.values()) {
            bins[s.ordinal()] = new int[s.bins()];
        }
    }

    /** A count's offset from its least value: the bin drawn. */
    int count(DrawSite site, RandomGenerator random) {
        double u = random.nextDouble();
        int bin = tilt.tilts(site) ? tilt.bin(site, u) : (int) (u * site.bins());
        trace(site, bin);
        return bin;
    }

    /** A coordinate in [0, 1): uniform within the bin drawn. */
    double coordinate(DrawSite site, RandomGenerator random) {
        double u = random.nextDouble();
        if (!tilt.tilts(site)) {
            trace(site, Math.min(site.bins() - 1, (int) (u * site.bins())));
            return u;
        }
        int bin = tilt.bin(site, u);
        trace(site, bin);
        // u given its bin is uniform over the bin's share of [0, 1): rescaled, it is uniform within the bin
        double within = (u - tilt.below(site, bin)) / tilt.probability(site, bin);
        double v = (bin + Math.max(0, within)) / site.bins();
        return Math.min(v, Math.nextDown((bin + 1.0) / site.bins()));
    }

    private void trace(DrawSite site, int bin) {
        bins[site.ordinal()][bin]++;
        double q = tilt.probability(site, bin);
        // a count's bin has probability 1/bins under the generator; a coordinate has density 1 on [0, 1)
        logNominal += site.isCount() ? -Math.log(site.bins()) : 0;
        logProposal += site.isCount() ? Math.log(q) : Math.log(q * site.bins());
    }

    /** What was drawn so far. */
    public DrawTrace trace() {
        int[][] copy = new int[bins.length][];
        for (int s = 0; s < bins.length; s++) {
            copy[s] = bins[s].clone();
        }
        return new DrawTrace(logNominal, logProposal, copy);
    }
}
