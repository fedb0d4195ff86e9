package sitcov.analysis;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import sitcov.coverage.GridDefinition;
import sitcov.experiment.CampaignConfig;
import sitcov.experiment.CampaignTarget;
import sitcov.experiment.StopReason;
import sitcov.faults.Fault;
import sitcov.judge.FaultyRuns;

/**
 * A campaign whose two faults each separate the drivers, in opposite directions: driver a falsifies fault
 * 2 at 10, 20 and 30 ticks and never fault 4; b the reverse; every unfalsified trial is censored at 100.
 * The numbers below are worked by hand from the log-rank and Fisher formulas.
 */
class CampaignAnalysisTest {
    private static final sitcov.judge.Variant X = new sitcov.judge.Variant.Seeded(Fault.ofId(2));
    private static final sitcov.judge.Variant Y = new sitcov.judge.Variant.Seeded(Fault.ofId(4));

    private static CampaignTrial trial(sitcov.judge.Variant f, String driver, int trial, boolean falsified, long ticks) {
        CampaignTarget target = new CampaignTarget.OfVariant(f);
        Optional<CampaignTrial.FoundMap> found = falsified
                ? Optional.of(new CampaignTrial.FoundMap(0, "seed:" + trial, trial, trial, trial)) : Optional.empty();
        return new CampaignTrial(target, driver, trial, 7, "replication-" + trial, falsified, ticks, ticks, 1,
                falsified ? StopReason.FALSIFIED : StopReason.TICKS, found,
                falsified ? Optional.of(sitcov.oracle.Failure.LEAVEROAD) : Optional.empty());
    }

    private static CampaignAnalysis analysis() {
        CampaignConfig config = new CampaignConfig("c", 1, CampaignConfig.ofVariants(List.of(X, Y)), List.of("a", "b"), 3, 100, 10,
                GridDefinition.paper(), FaultyRuns.UNTIL_VERDICT, "builtin");
        List<CampaignTrial> trials = new ArrayList<>();
        for (int t = 0; t < 3; t++) {
            trials.add(trial(X, "a", t, true, 10 * (t + 1)));
            trials.add(trial(X, "b", t, false, 100));
            trials.add(trial(Y, "a", t, false, 100));
            trials.add(trial(Y, "b", t, true, 10 * (t + 1)));
        }
        return CampaignAnalysis.of(config, trials);
    }

    @Test
    void eachDriverHasItsFalsifiedTrialsKaplanMeierMedianAndDistinctFailures() {
        CampaignAnalysis.DriverResult ax = analysis().drivers().get(0);
        assertEquals(new CampaignTarget.OfVariant(X), ax.target());
        assertEquals("a", ax.driver());
        assertEquals(3, ax.falsified());
        // survival 2/3 after 10, 1/3 after 20: the first time at or below one half is 20
        assertEquals(20, ax.medianTicks().getAsDouble(), 1e-12);
        assertEquals(3, ax.distinctFailures(), "three cells, one accident type");
        CampaignAnalysis.DriverResult bx = analysis().drivers().get(1);
        assertTrue(bx.medianTicks().isEmpty(), "never falsified: the median is not reached");
        assertEquals(0, bx.distinctFailures());
    }

    @Test
    void perFaultTestsAreOneHolmFamilyOfFisherAndLogRank() {
        CampaignAnalysis.PairTest x = analysis().pairs().get(0);
        // 3 of 3 against 0 of 3: the only more extreme table is itself, twice (both tails): 2 / C(6,3) = 0.1
        assertEquals(0.1, x.fisherP(), 1e-9);
        // O = 3; E = 3/6 + 2/5 + 1/4 = 1.15; V = 0.25 + 0.24 + 0.1875 = 0.6775
        assertEquals(3, x.logRank().observedA(), 1e-12);
        assertEquals(1.15, x.logRank().expectedA(), 1e-12);
        assertEquals(0.6775, x.logRank().variance(), 1e-12);
        // four tests: log-rank p 0.0246 twice (Holm: 4 × p), Fisher 0.1 twice (Holm: 2 × 0.1)
        assertEquals(4 * x.logRank().p(), x.logRankHolm(), 1e-12);
        assertEquals(0.2, x.fisherHolm(), 1e-9);
    }

    @Test
    void oppositeFaultsCancelInTheLogRankTestStratifiedByFault() {
        CampaignAnalysis.Stratified s = analysis().stratified().get(0);
        // fault 2 gives a O − E = 3 − 1.15, fault 4 gives 0 − 1.85: the sums agree, so nothing is shown
        assertEquals(3, s.observedA(), 1e-12);
        assertEquals(3, s.expectedA(), 1e-12);
        assertEquals(2 * 0.6775, s.variance(), 1e-12);
        assertEquals(1, s.p(), 1e-12);
        assertFalse(s.aSooner());
        for (CampaignAnalysis.Overall o : analysis().overall()) {
            assertEquals(1, o.anyTrial(), o.driver());
            assertEquals(1, o.majority(), o.driver());
        }
    }
}
