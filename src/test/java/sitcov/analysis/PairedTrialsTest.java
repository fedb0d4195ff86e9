package sitcov.analysis;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import sitcov.coverage.GridDefinition;
import sitcov.experiment.CampaignConfig;
import sitcov.experiment.CampaignTarget;
import sitcov.experiment.StopReason;
import sitcov.judge.FaultyRuns;
import sitcov.judge.Requirement;
import sitcov.oracle.Failure;

/**
 * A campaign of two requirements over 10 paired trials, budget 1000. Timeout: a falsifies trials 0..7 (at 100 (t + 1)
 * ticks, after t + 1 maps), b trials 0 (at 150) and 8 (at 50); trial 9 neither: McNemar's b = 7, c = 1, and a fell
 * first in 8 trials, b in 1. Obstacle: a falsifies trials 0..2, b trial 3: 4 discordant trials, too few to test.
 */
class PairedTrialsTest {
    private static final CampaignTarget TIMEOUT = new CampaignTarget.OfRequirement(Requirement.TIMEOUT);
    private static final CampaignTarget OBSTACLE = new CampaignTarget.OfRequirement(Requirement.OBSTACLE);

    private static CampaignTrial trial(CampaignTarget target, String driver, int t, long ticks, int maps) {
        if (ticks < 0) {
            return new CampaignTrial(target, driver, t, 7, "replication-" + t, false, 1000, 1000, 40, StopReason.TICKS,
                    Optional.empty(), Optional.empty());
        }
        return new CampaignTrial(target, driver, t, 7, "replication-" + t, true, ticks, ticks, maps, StopReason.FALSIFIED,
                Optional.of(new CampaignTrial.FoundMap(maps - 1, "seed:" + t, t, t, t)), Optional.of(Failure.TIMEOUT));
    }

    private static CampaignAnalysis analysis() {
        List<CampaignTrial> trials = new ArrayList<>();
        for (int t = 0; t < 10; t++) {
            trials.add(trial(TIMEOUT, "a", t, t < 8 ? 100 * (t + 1) : -1, t + 1));
            trials.add(trial(TIMEOUT, "b", t, t == 0 ? 150 : t == 8 ? 50 : -1, 2));
            trials.add(trial(OBSTACLE, "a", t, t < 3 ? 500 : -1, 3));
            trials.add(trial(OBSTACLE, "b", t, t == 3 ? 500 : -1, 3));
        }
        CampaignConfig config = new CampaignConfig("c", 1, CampaignConfig.ofRequirements(List.of(Requirement.OBSTACLE,
                Requirement.TIMEOUT)), List.of("a", "b"), 10, 1000, 10, GridDefinition.paper(), FaultyRuns.UNTIL_VERDICT,
                "exec:mine");
        return CampaignAnalysis.of(config, trials);
    }

    @Test
    void mcNemarAndTheLogRankTestByTrialAreOneHolmFamily() {
        PairedTrials timeout = analysis().paired().get(1);
        assertEquals(TIMEOUT, timeout.target());
        assertEquals(7, timeout.onlyA());
        assertEquals(1, timeout.onlyB());
        // McNemar: 2 P(X <= 1), X ~ Bin(8, 1/2) = 18/256
        assertEquals(0.0703125, timeout.mcNemarP(), 1e-12);
        // a first in 8 trials, b in 1: 2 P(X <= 1), X ~ Bin(9, 1/2) = 20/512
        assertEquals(8, timeout.logRank().firstA());
        assertEquals(1, timeout.logRank().firstB());
        assertEquals(0.0390625, timeout.logRankP(), 1e-12);
        // the family holds these two tests only: Holm gives 2 x 0.039 = 0.078 and max(0.078, 0.070) = 0.078
        assertEquals(0.078125, timeout.logRankHolm(), 1e-12);
        assertEquals(0.078125, timeout.mcNemarHolm(), 1e-12);
        assertEquals("", timeout.why());
    }

    @Test
    void testsOnFewerThanSixDiscordantTrialsAreDescribedNotMade() {
        PairedTrials obstacle = analysis().paired().get(0);
        assertEquals(3, obstacle.onlyA());
        assertEquals(1, obstacle.onlyB());
        assertTrue(Double.isNaN(obstacle.mcNemarP()) && Double.isNaN(obstacle.mcNemarHolm()));
        assertTrue(Double.isNaN(obstacle.logRankP()) && Double.isNaN(obstacle.logRankHolm()));
        assertEquals("McNemar: 4 trials falsified by one driver only: cannot reach 0.05; log-rank: 4 trials with one"
                + " driver first: cannot reach 0.05", obstacle.why());
    }

    @Test
    void eachDriverHasItsShareWithWilsonsIntervalAndTheMeansOverItsFalsifiedTrials() {
        CampaignAnalysis.DriverResult a = analysis().drivers().get(2);
        assertEquals(TIMEOUT, a.target());
        assertEquals("a", a.driver());
        // Wilson, 8 of 10: (16 + z^2 -+ z sqrt(z^2 + 6.4)) / (2 (10 + z^2)) = 0.4902 and 0.9433
        assertEquals(0.4902, a.share().low(), 5e-5);
        assertEquals(0.9433, a.share().high(), 5e-5);
        // ticks 100..800: mean 450; maps 1..8: median 4.5, mean 4.5
        assertEquals(450, a.meanTicks().getAsDouble(), 1e-12);
        assertEquals(4.5, a.medianMaps().getAsDouble(), 1e-12);
        assertEquals(4.5, a.meanMaps().getAsDouble(), 1e-12);
        // survival 0.9, 0.8, ... after 100, 200, ...: first at or below 0.5 at 500
        assertEquals(500, a.medianTicks().getAsDouble(), 1e-12);
        CampaignAnalysis.DriverResult b = analysis().drivers().get(3);
        assertEquals(2, b.falsified());
        assertEquals(100, b.meanTicks().getAsDouble(), 1e-12, "50 and 150");
        assertTrue(b.medianTicks().isEmpty(), "8 of 10 trials censored: the curve stays at 0.8");
    }
}
