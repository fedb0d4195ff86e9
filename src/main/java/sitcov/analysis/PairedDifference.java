package sitcov.analysis;

import sitcov.stats.ConfidenceInterval;

/**
 * A quantity measured once per replication for each of two drivers, compared pair by pair: the two
 * means, the mean paired difference (earlier minus later driver) with its bootstrap 95 % CI and the
 * standard deviation of the differences ({@code spread}); how many replications differ at all, in how
 * many the earlier driver is higher ({@code higherA}), and which way their signed ranks lean (+1
 * towards the earlier driver, −1 the later, 0 neither); the signed-rank p as tested ({@code p}:
 * two-sided unless a directional primary question) and as its family adjusts it ({@code pAdjusted}:
 * the same for the primary test, NaN where not tested); the smallest p the test could give on
 * differences of these sizes; and the smallest difference it could have detected with 80 % power at
 * the level it was held to (NaN where not tested).
 */
public record PairedDifference(int replications, double meanA, double meanB, ConfidenceInterval difference, double spread,
                               int differing, int higherA, int lean, double p, double smallestP, double pAdjusted,
                               double detectable) {
    PairedDifference adjusted(double pAdjusted, double detectable) {
        return new PairedDifference(replications, meanA, meanB, difference, spread, differing, higherA, lean, p, smallestP,
                pAdjusted, detectable);
    }

    /** Replications in which the later driver is higher. */
    public int higherB() {
        return differing - higherA;
    }

    /**
     * The paired effect size: the share of replications in which the earlier driver is higher, ties
     * counted half — the probability that a paired difference is positive, 0.5 where neither leads
     * (Â12's paired counterpart: Â12 compares every replication with every other, this one each with
     * its own pair). NaN with no replications.
     */
    public double superiority() {
        return replications == 0 ? Double.NaN : (higherA + 0.5 * (replications - differing)) / replications;
    }
}
