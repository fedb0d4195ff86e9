package sitcov.analysis;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import sitcov.experiment.DriverRun;
import sitcov.experiment.MapRun;
import sitcov.experiment.ReplicationResult;

class SituationFaultsTest {
    private static ReplicationResult replication(DriverRun... runs) {
        return new ReplicationResult(0, List.of(runs));
    }

    @Test
    void theCellExplainsAThirdOfTheVarianceOnAHandWorkedExample() {
        // cell 1: three maps, one finds fault 14; cell 2: one map, which finds it. Mean 1/2, total sum of
        // squares 4 * 1/4 = 1; between cells 3 * (1/3 - 1/2)^2 + 1 * (1 - 1/2)^2 = 1/12 + 3/12 = 1/3
        SituationFaults s = SituationFaults.of(List.of(replication(DiscoveryTest.run("random",
                DiscoveryTest.map("random", 0, 0, 1, "F-"), DiscoveryTest.map("random", 1, 1, 1, "--"),
                DiscoveryTest.map("random", 2, 2, 1, "--"), DiscoveryTest.map("random", 3, 3, 2, "F-")))),
                DiscoveryTest.FAULTS);
        assertEquals(Map.of(1, 3, 2, 1), s.mapsOfCell());
        assertArrayEquals(new int[] {1, 0}, s.foundIn(1));
        SituationFaults.Uniformity u = s.uniformity(50, new SplittableRandom(1)).get(0);
        assertEquals(1.0 / 3, u.explained(), 1e-12);
        assertEquals(2, u.found());
        assertEquals(0, s.uniformity(50, new SplittableRandom(1)).get(1).explained(), "fault 19 is found nowhere");
    }

    @Test
    void cellsThatDecideDetectionExplainItAllAndBeatEveryRandomDeal() {
        List<MapRun> maps = new ArrayList<>();
        for (int i = 0; i < 20; i++) {
            maps.add(DiscoveryTest.map("random", i, i, i < 10 ? 4 : 8, i < 10 ? "F-" : "--"));
        }
        SituationFaults s = SituationFaults.of(List.of(replication(DiscoveryTest.run("random", maps.toArray(MapRun[]::new)))),
                DiscoveryTest.FAULTS);
        SituationFaults.Uniformity u = s.uniformity(200, new SplittableRandom(7)).get(0);
        assertEquals(1, u.explained(), 1e-12);
        // a random deal of 10 finding maps into two cells of 10 is as good only with odds 2 / C(20,10) ≈ 1e-5
        assertEquals(1.0 / 201, u.p(), 1e-12);
        assertTrue(u.byChance() < 0.2, "by chance " + u.byChance());
    }

    @Test
    void aMapTwoDriversShareCountsOnce() {
        MapRun shared = DiscoveryTest.map("coverage-filter", 0, 3, 5, "F-");
        MapRun same = DiscoveryTest.map("random", 0, 3, 5, "F-");
        SituationFaults s = SituationFaults.of(List.of(replication(DiscoveryTest.run("coverage-filter", shared),
                DiscoveryTest.run("random", same, DiscoveryTest.map("random", 1, 4, 5, "--")))), DiscoveryTest.FAULTS);
        assertEquals(Map.of(5, 2), s.mapsOfCell());
    }
}
