package sitcov.verdict;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import sitcov.analysis.CampaignAnalysis;
import sitcov.analysis.CampaignTrial;
import sitcov.coverage.GridDefinition;
import sitcov.experiment.CampaignConfig;
import sitcov.experiment.CampaignTarget;
import sitcov.experiment.StopReason;
import sitcov.faults.Fault;
import sitcov.judge.FaultyRuns;

class CampaignVerdictTest {
    private static final sitcov.judge.Variant F = new sitcov.judge.Variant.Seeded(Fault.ofId(2));
    private static final CampaignTarget TARGET = new CampaignTarget.OfVariant(F);

    private static CampaignTrial trial(String driver, int t, long ticks) {
        if (ticks < 0) {
            return new CampaignTrial(TARGET, driver, t, 7, "replication-" + t, false, 100, 100, 3, StopReason.TICKS,
                    Optional.empty(), Optional.empty());
        }
        return new CampaignTrial(TARGET, driver, t, 7, "replication-" + t, true, ticks, ticks, 1, StopReason.FALSIFIED,
                Optional.of(new CampaignTrial.FoundMap(0, "seed:" + t, t, t, t)), Optional.of(sitcov.oracle.Failure.TIMEOUT));
    }

    private static List<String> verdict(List<CampaignTrial> trials, int n) {
        CampaignConfig config = new CampaignConfig("c", 1, List.of(TARGET), List.of("a", "b"), n, 100, 10, GridDefinition.paper(),
                FaultyRuns.UNTIL_VERDICT, "builtin");
        return CampaignVerdict.lines(CampaignAnalysis.of(config, trials));
    }

    @Test
    void aDriverThatFalsifiesEveryTrialEarlyIsSaidToFalsifySooner() {
        List<CampaignTrial> trials = new ArrayList<>();
        for (int t = 0; t < 3; t++) {
            trials.add(trial("a", t, 10 * (t + 1)));
            trials.add(trial("b", t, -1));
        }
        List<String> lines = verdict(trials, 3);
        assertEquals("a falsified 1 of the 1 faults in at least one trial, 1 in a majority of its trials.", lines.get(1));
        assertEquals("b falsified 0 of the 1 faults in at least one trial, 0 in a majority of its trials.", lines.get(2));
        // log-rank chi-square (3 − 1.15)² / 0.6775 = 5.05, p = 0.025: shown, a ahead
        assertTrue(lines.get(3).startsWith("Over all faults, a falsifies sooner than b"), lines.get(3));
        // of the fault's two tests, log-rank's Holm p is 2 × 0.025 = 0.049 and Fisher's 0.1: only log-rank shows it
        assertTrue(lines.get(4).contains("fault 2: a ahead of b (3 against 0 trials falsified, log-rank Holm p = 0.049)"),
                lines.get(4));
    }

    @Test
    void whenNothingIsShownTheVerdictSaysSoWithoutCallingThemEqual() {
        List<CampaignTrial> trials = List.of(trial("a", 0, 40), trial("b", 0, 50), trial("a", 1, -1), trial("b", 1, -1));
        List<String> lines = verdict(trials, 2);
        assertTrue(lines.get(3).startsWith("Over all faults, no difference in ticks to first failure is shown between a and b"),
                lines.get(3));
        assertTrue(lines.get(3).endsWith("that is not evidence that they are equal."), lines.get(3));
        assertTrue(lines.get(4).contains("even 2 of 2 against 0 of 2 falsified gives Fisher p = 0.333"), lines.get(4));
    }
}
