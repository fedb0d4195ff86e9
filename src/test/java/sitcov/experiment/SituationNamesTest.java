package sitcov.experiment;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import org.junit.jupiter.api.Test;
import sitcov.coverage.GridDefinition;
import sitcov.faults.FaultSet;
import sitcov.judge.FaultyRuns;
import sitcov.world.MapGenerator;

/** A built situation's name is its identity: two drivers of one replication never share one. */
class SituationNamesTest {
    private static final ExperimentConfig TWO_BUILDERS = new ExperimentConfig("names", 9, 8, 1, FaultSet.parse("19"),
            BudgetKind.TICKS, GridDefinition.paper(), List.of("a", "b"), List.of(), 8, FaultyRuns.UNTIL_VERDICT);

    /** The seed each built situation was generated from, by driver and name, as the drivers built them. */
    private final Map<String, Long> builtFrom = new ConcurrentHashMap<>();

    /**
     * A driver that builds two situations, named {@code prefix0} and {@code prefix1}, from the runnable
     * candidates it draws after skipping {@code skip} of them (so two builders given different skips
     * build different worlds from the one candidate stream they share).
     */
    private Driver builder(String driver, String prefix, int skip) {
        return session -> {
            int runnable = 0;
            int built = 0;
            while (session.budgetLeft()) {
                Candidate c = session.nextCandidate();
                if (c.runnable() && runnable++ >= skip && built < 2) {
                    String name = prefix + built++;
                    builtFrom.put(driver + "/" + name, c.externalSeed());
                    session.run(name, MapGenerator.generate(c.externalSeed()));
                }
            }
        };
    }

    @Test
    void twoDriversOfOneReplicationBuildSituationsUnderTheirOwnNamesAndEachIsJudgedOnItsOwnWorld() {
        DriverFactory drivers = name -> builder(name, name + "-r0-", name.equals("a") ? 0 : 1);
        List<MapRun> maps = ResultsCollector.run(TWO_BUILDERS, drivers, 1).get(0).drivers().stream()
                .flatMap(d -> d.maps().stream()).toList();

        assertTrue(maps.stream().anyMatch(m -> m.driver().equals("b")), "driver b ran no map: " + maps);
        for (MapRun m : maps) {
            String name = ((MapId.Situation) m.map()).name();
            assertTrue(name.startsWith(m.driver() + "-"), name);
            assertEquals(builtFrom.get(m.driver() + "/" + name), m.externalSeed(), "the world " + name + " was judged on");
        }
    }

    @Test
    void aDriverReusingANameAnotherDriverOfTheReplicationRanIsRefusedNotGivenTheFirstOnesWorld() {
        DriverFactory drivers = name -> builder(name, "shared-", name.equals("a") ? 0 : 1);

        IllegalStateException e = assertThrows(IllegalStateException.class,
                () -> ResultsCollector.run(TWO_BUILDERS, drivers, 1));

        // on one thread the first driver runs first, so it is b that reuses a's name
        assertNotEquals(builtFrom.get("a/shared-0"), builtFrom.get("b/shared-0"), "the two builders built different worlds");
        assertTrue(e.getMessage().contains("driver b ran situation shared-0 in replication 0, but driver a ran a situation"
                + " of that name before"), e.getMessage());
        assertTrue(e.getMessage().contains("situations/shared-0.situation"), e.getMessage());
    }

    @Test
    void aDriverRunningOneOfItsOwnNamesAgainIsRefused() {
        ExperimentConfig one = new ExperimentConfig("again", 9, 8, 1, FaultSet.parse("19"), BudgetKind.TICKS,
                GridDefinition.paper(), List.of("a"), List.of(), 8, FaultyRuns.UNTIL_VERDICT);
        IllegalStateException e = assertThrows(IllegalStateException.class,
                () -> ResultsCollector.run(one, name -> session -> {
                    Candidate c = session.nextCandidate();
                    while (!c.runnable()) {
                        c = session.nextCandidate();
                    }
                    session.run("same", MapGenerator.generate(c.externalSeed()));
                    session.run("same", MapGenerator.generate(c.externalSeed()));
                }, 1));
        assertTrue(e.getMessage().contains("driver a ran situation same in replication 0, but it ran a situation of that"
                + " name before"), e.getMessage());
    }
}
