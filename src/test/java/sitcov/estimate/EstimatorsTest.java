package sitcov.estimate;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import sitcov.oracle.Failure;
import sitcov.world.DrawSite;
import sitcov.world.DrawTrace;

class EstimatorsTest {
    static Sample sample(int replication, double logNominal, double logProposal, boolean failed) {
        return sample(replication, "is", logNominal, logProposal, failed);
    }

    static Sample sample(int replication, String stage, double logNominal, double logProposal, boolean failed) {
        int[][] bins = new int[DrawSite.values().length][];
        for (DrawSite s : DrawSite.values()) {
            bins[s.ordinal()] = new int[s.bins()];
        }
        return new Sample(replication, stage, 0, 0, new DrawTrace(logNominal, logProposal, bins), 100,
                failed ? -1 : 1, failed ? Set.of(Failure.TIMEOUT) : Set.of());
    }

    @Test
    void plainMonteCarloIsTheShareOfFailingRunsWithWilsonsInterval() {
        List<Sample> runs = new ArrayList<>();
        for (int i = 0; i < 40; i++) {
            runs.add(sample(0, 0, 0, i < 4));
        }
        Estimate e = Estimators.monteCarlo(runs, new Failing.Any());
        assertEquals(0.1, e.rate(), 1e-15);
        double z = 1.959963984540054;
        double n = 40;
        double p = 0.1;
        double centre = (p + z * z / (2 * n)) / (1 + z * z / n);
        double half = z / (1 + z * z / n) * Math.sqrt(p * (1 - p) / n + z * z / (4 * n * n));
        assertEquals(centre - half, e.low(), 1e-12);
        assertEquals(centre + half, e.high(), 1e-12);
        assertEquals(4000, e.ticks());
    }

    @Test
    void importanceSamplingWithEveryWeightOneIsPlainMonteCarloWithANormalInterval() {
        List<Sample> runs = new ArrayList<>();
        for (int i = 0; i < 50; i++) {
            runs.add(sample(0, -2, -2, i % 5 == 0));
        }
        Estimate e = Estimators.importanceSampling(runs, new Failing.Any());
        assertEquals(0.2, e.rate(), 1e-12);
        assertEquals(50, e.ess(), 1e-9);
        double sd = Math.sqrt(0.2 * 0.8 * 50 / 49);
        assertEquals(1.959963984540054 * sd / Math.sqrt(50), e.halfWidth(), 1e-12);
    }

    @Test
    void importanceSamplingFindsAKnownSmallProbabilityWithinItsInterval() {
        // a failure of probability 0.002 under the nominal law, drawn 100 times as often under the proposal
        double p = 0.002;
        double q = 0.2;
        SplittableRandom random = new SplittableRandom(11);
        List<Sample> runs = new ArrayList<>();
        for (int i = 0; i < 2000; i++) {
            boolean failed = random.nextDouble() < q;
            runs.add(failed ? sample(0, Math.log(p), Math.log(q), true) : sample(0, Math.log(1 - p), Math.log(1 - q), false));
        }
        Estimate e = Estimators.importanceSampling(runs, new Failing.Any());
        assertTrue(e.low() <= p && p <= e.high(), e.toString());
        // plain Monte Carlo would need about (1 - p) / p / (relative half-width / 1.96)^2 runs for the same precision
        assertTrue(e.relativeHalfWidth() < 0.1, e.toString());
    }

    @Test
    void replicationsAreStrataWhoseVariancesAdd() {
        List<Sample> runs = new ArrayList<>();
        for (int i = 0; i < 10; i++) {
            runs.add(sample(0, 0, 0, i < 5));
            runs.add(sample(1, 0, 0, false));
        }
        Estimate e = Estimators.importanceSampling(runs, new Failing.Any());
        assertEquals(0.25, e.rate(), 1e-12);
        // stratum 0: its runs vary by 0.5·0.5·10/9, its mean by a tenth of that; stratum 1 not at all; each weighs (10/20)²
        double variance = (0.5 * 0.5) * (0.25 * 10 / 9) / 10;
        assertEquals(1.959963984540054 * Math.sqrt(variance), e.halfWidth(), 1e-12);
    }

    @Test
    void theStagesOfOneReplicationAreStrataToo() {
        // each stage drew from a proposal of its own: a cross-entropy stage from the generator (weight 1), the final
        // stage from a proposal that draws the failing maps 4 times as often (weight 1/4 on them)
        List<Sample> runs = new ArrayList<>();
        for (int i = 0; i < 10; i++) {
            runs.add(sample(0, "ce-1", 0, 0, i < 1));
            runs.add(sample(0, "is", 0, Math.log(4), i < 4));
        }
        Estimate e = Estimators.importanceSampling(runs, new Failing.Any());
        // the pooled mean of w·1{failed}: (1 + 4 / 4) / 20
        assertEquals(0.1, e.rate(), 1e-12);
        // ce-1: mean 0.1, sample variance (1 - 10·0.01) / 9 = 0.1; is: mean 0.1, sample variance 4·(1/16 - 0.01·10/4) / 9
        double ceVariance = 0.1;
        double isVariance = (4 * 0.0625 - 10 * 0.01) / 9;
        double variance = 0.25 * ceVariance / 10 + 0.25 * isVariance / 10;
        assertEquals(1.959963984540054 * Math.sqrt(variance), e.halfWidth(), 1e-12);
    }

    @Test
    void eachRequirementCountsOnlyItsOwnFailures() {
        List<Sample> runs = List.of(sample(0, 0, 0, true), sample(0, 0, 0, false));
        assertEquals(0.5, Estimators.monteCarlo(runs, new Failing.Of(sitcov.judge.Requirement.TIMEOUT)).rate());
        assertEquals(0.0, Estimators.monteCarlo(runs, new Failing.Of(sitcov.judge.Requirement.LEAVEROAD)).rate());
    }
}
