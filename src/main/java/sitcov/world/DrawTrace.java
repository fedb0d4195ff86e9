package sitcov.world;

/**
 * The key draws that made one map ({@link Draws}): how many fell in each bin of each site, and
 * their log-likelihood under the generator and under the proposal that drew them. The draws at no
 * site have the same law under both and cancel from the ratio.
 *
 * @param bins per {@link DrawSite} (by ordinal), the draws in each bin
 */
public record DrawTrace(double logNominal, double logProposal, int[][] bins) {
    /** The importance weight p_nominal / p_proposal of the map. */
    public double weight() {
        return Math.exp(logNominal - logProposal);
    }

    /** How many draws of {@code site} fell in bin {@code bin}. */
    public int draws(DrawSite site, int bin) {
        return bins[site.ordinal()][bin];
    }
}
