package sitcov.results;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import sitcov.analysis.Summary;
import sitcov.coverage.GridDefinition;
import sitcov.experiment.BudgetKind;
import sitcov.experiment.DriverRun;
import sitcov.experiment.DriverSpend;
import sitcov.experiment.ExperimentConfig;
import sitcov.experiment.MapId;
import sitcov.experiment.MapRun;
import sitcov.experiment.ReplicationResult;
import sitcov.experiment.StopReason;
import sitcov.faults.Fault;
import sitcov.faults.FaultSet;
import sitcov.judge.Detection;
import sitcov.judge.FaultOutcome;
import sitcov.judge.RunSummary;
import sitcov.oracle.AccidentType;
import sitcov.oracle.Outcome;

class ResultsTablesTest {
    private static final ExperimentConfig CONFIG = new ExperimentConfig("tables", 1, 10, 2, FaultSet.parse("14,19"),
            BudgetKind.TICKS, GridDefinition.paper());
    private static final RunSummary SAFE = new RunSummary(Outcome.TARGET_REACHED, 100, List.of(0L, 0L, 0L, 0L, 0L));

    /** A map in {@code cell}; marks per fault (14, 19): F found, P only by the paper's notion, - neither. */
    private static MapRun map(int replication, String driver, int index, int cell, String marks) {
        List<FaultOutcome> faults = new ArrayList<>();
        List<Fault> ids = List.of(Fault.TARGET_LANE_CHECK_SKIPPED, Fault.ONCOMING_AT_HALF_SPEED);
        for (int f = 0; f < 2; f++) {
            char m = marks.charAt(f);
            faults.add(new FaultOutcome(new sitcov.judge.Variant.Seeded(ids.get(f)), SAFE, true, true, 1, m == 'F' ? Detection.FOUND : Detection.EFFECT_NO_FAILURE,
                    m == 'F' ? Optional.of(sitcov.oracle.Failure.LEAVEROAD) : Optional.empty(), m != '-'));
        }
        return new MapRun(replication, driver, index, index, new MapId.Seeded(index), index, index, cell,
                List.of(0.0, 0.0, 0.0), SAFE, faults);
    }

    private static DriverRun run(int replication, String driver, MapRun... maps) {
        long cells = List.of(maps).stream().mapToInt(MapRun::cell).distinct().count();
        return new DriverRun(driver, List.of(maps), new DriverSpend(replication, driver, 10, maps.length,
                maps.length * 300L, (int) cells, StopReason.CANDIDATES));
    }

    // replication 0: the filter finds 14 on both maps, 19 on one; random finds 14 on one of three
    // replication 1: the filter finds 14 on its one map; random finds nothing on two maps (19 only by the paper's notion)
    private static final Summary SUMMARY = new Summary(CONFIG, List.of(
            new ReplicationResult(0, List.of(
                    run(0, "coverage-filter", map(0, "coverage-filter", 0, 5, "FF"), map(0, "coverage-filter", 1, 6, "F-")),
                    run(0, "random", map(0, "random", 0, 5, "F-"), map(0, "random", 1, 5, "--"), map(0, "random", 2, 7, "--")))),
            new ReplicationResult(1, List.of(
                    run(1, "coverage-filter", map(1, "coverage-filter", 0, 9, "F-")),
                    run(1, "random", map(1, "random", 0, 9, "-P"), map(1, "random", 1, 9, "--"))))));

    @Test
    void summaryCsvHasTheMeasuresPerDriverReplicationAndNotionWorkedOutByHand() {
        List<String> rows = new ResultsTables(CONFIG, SUMMARY).summary();
        assertEquals("driver,replication,notion,maps_run,cells_covered,cells_total,cells_seen,method_prop_fault,prop_map_all_fault,"
                + "avg_map_fault,fault_14,fault_19", rows.get(0));
        // cells seen by any driver in any replication: 5, 6 (filter), 7 (random), 9 (both): 4
        // filter, replication 0: 2 maps, 2 cells, both faults found somewhere, 1 of 2 maps finds both, 3 finds / 2 maps
        assertEquals("coverage-filter,0,differential,2,2,216,4,1.0000,0.5000,1.5000,1.0000,0.5000", rows.get(1));
        // random, replication 0: 3 maps in 2 cells, only 14 found (once): 1/2, 0, 1/3
        assertEquals("random,0,differential,3,2,216,4,0.5000,0.0000,0.3333,0.3333,0.0000", rows.get(3));
        // random, replication 1, paper's notion: fault 19 on one map of two
        assertEquals("random,1,paper,2,1,216,4,0.5000,0.0000,0.5000,0.0000,0.5000", rows.get(8));
        assertEquals(1 + 2 * 2 * 2, rows.size());
    }

    @Test
    void table2HasEachDriversMeanShareAndThePairsDifferenceWorkedOutByHand() {
        List<String> rows = new ResultsTables(CONFIG, SUMMARY).table2();
        assertEquals("fault,name,notion,coverage-filter,random,coverage-filter_minus_random", rows.get(0));
        // fault 14, differential: filter (2/2 + 1/1)/2 = 1; random (1/3 + 0/2)/2 = 1/6; difference 5/6
        assertEquals("14,target-lane-check-skipped,differential,1.0000,0.1667,0.8333", rows.get(1));
        // fault 19, paper: filter (1/2 + 0)/2 = 0.25; random (0 + 1/2)/2 = 0.25
        assertEquals("19,oncoming-at-half-speed,paper,0.2500,0.2500,0.0000", rows.get(4));
    }

    @Test
    void theCoverageCurveHasAPointPerNewCellAndOneWhereTheDriverStopped() {
        List<String> rows = new ResultsTables(CONFIG, SUMMARY).curve();
        assertEquals(List.of("driver,replication,candidates,maps_run,ticks,cells_covered",
                "coverage-filter,0,1,1,300,1", "coverage-filter,0,2,2,600,2", "coverage-filter,0,10,2,600,2",
                "random,0,1,1,300,1", "random,0,3,3,900,2", "random,0,10,3,900,2",
                "coverage-filter,1,1,1,300,1", "coverage-filter,1,10,1,300,1",
                "random,1,1,1,300,1", "random,1,10,2,600,1"), rows);
    }
}
