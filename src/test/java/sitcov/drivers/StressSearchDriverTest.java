package sitcov.drivers;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import sitcov.coverage.GridDefinition;
import sitcov.experiment.BudgetKind;
import sitcov.experiment.DriverRun;
import sitcov.experiment.ExperimentConfig;
import sitcov.experiment.MapId;
import sitcov.experiment.MapRun;
import sitcov.experiment.ReplicationResult;
import sitcov.experiment.ResultsCollector;
import sitcov.faults.FaultSet;
import sitcov.judge.FaultyRuns;
import sitcov.judge.Requirement;

class StressSearchDriverTest {
    private static ExperimentConfig search(String faults) {
        return new ExperimentConfig("stress", 42, CANDIDATES, 1, FaultSet.parse(faults), BudgetKind.TICKS,
                GridDefinition.paper(), List.of("stress-search"), List.of(), CANDIDATES, FaultyRuns.UNTIL_VERDICT);
    }

    private static final int CANDIDATES = 30;
    /** The search with fault 19, on one thread: run once for all the tests. */
    private static final List<ReplicationResult> WITH_19 = ResultsCollector.run(search("19"), Drivers.standard(), 1);

    private static DriverRun run(String faults) {
        List<ReplicationResult> results = faults.equals("19") ? WITH_19
                : ResultsCollector.run(search(faults), Drivers.standard(), 1);
        return results.get(0).of("stress-search");
    }

    /** What the search chose to run, and all it may see of it: the map, its cell and the fault-free run. */
    private static List<String> choices(DriverRun run) {
        return run.maps().stream().map(m -> m.map().text() + " " + m.externalSeed() + " " + m.candidate() + " "
                + m.cell() + " " + m.faultFree()).toList();
    }

    @Test
    void theSearchChoosesTheSameSituationsWhateverTheFaultsDoSoItSeesOnlyTheReference() {
        DriverRun one = run("19");
        DriverRun other = run("3,14");
        assertNotEquals(one.maps().stream().map(MapRun::faults).toList(),
                other.maps().stream().map(MapRun::faults).toList(), "the faults' outcomes differ");
        assertEquals(choices(one), choices(other), "master seed 42");
    }

    @Test
    void theSearchRunsSituationsItBuiltPaidForWithCandidatesAndMeasuresEachRunsMargins() {
        DriverRun run = run("19");
        long built = run.maps().stream().filter(m -> m.map() instanceof MapId.Situation).count();
        assertTrue(built > 0, "no situation built in " + CANDIDATES + " candidates (master seed 42)");
        assertTrue(run.maps().stream().filter(m -> m.map() instanceof MapId.Situation s)
                .allMatch(m -> ((MapId.Situation) m.map()).name().startsWith("stress-r0-") && m.candidate() >= 0));
        assertEquals(CANDIDATES, run.spend().candidates(), "every edit tried is paid for with a candidate");
        assertTrue(run.maps().stream().allMatch(m -> m.faultFree().margins().known()), "every run's margins are measured");
    }

    @Test
    void theSearchIsTheSameOnEveryRun() {
        assertEquals(WITH_19, ResultsCollector.run(search("19"), Drivers.standard(), 2));
    }

    /** The search alone in the trial of a campaign of the reference's own {@code requirement}, master seed 42. */
    private static DriverRun falsifying(Requirement requirement) {
        ExperimentConfig c = new ExperimentConfig("req", 42, 1000, 1, List.of(), BudgetKind.FIXED_TICKS, GridDefinition.paper(),
                List.of("stress-search"), List.of(), 1000, FaultyRuns.UNTIL_VERDICT,
                sitcov.experiment.AnalysisPlan.defaults(List.of("stress-search")), "builtin", 8000,
                java.util.Optional.of(requirement));
        return ResultsCollector.run(c, Drivers.standard(), 1).get(0).of("stress-search");
    }

    @Test
    void inARequirementCampaignTheSearchSteersByThatRequirementsRobustnessAlone() {
        DriverRun edge = falsifying(Requirement.LEAVEROAD);
        DriverRun centre = falsifying(Requirement.CENTRELINE);
        // the same candidate stream and choices stream: only what the search reads as stress differs
        assertEquals(choices(edge).subList(0, 1), choices(centre).subList(0, 1), "the first map is drawn, not chosen");
        // compared over the maps both ran: a trial stops at its first violation, which may come sooner for one
        int both = Math.min(edge.maps().size(), centre.maps().size());
        assertNotEquals(choices(edge).subList(0, both), choices(centre).subList(0, both),
                "stress read from the road's edge or from the centre line");
        assertEquals(choices(edge), choices(falsifying(Requirement.LEAVEROAD)));
    }
}
