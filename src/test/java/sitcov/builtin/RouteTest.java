package sitcov.builtin;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;
import sitcov.geom.Compass;
import sitcov.world.Junction;
import sitcov.world.Layout;
import sitcov.world.RoadNetwork;
import sitcov.world.Situations;

class RouteTest {
    // The tee: T at (100, 30), dead ends at x = 13 and x = 187 on the main road and at (100, 87)
    // on the branch; the Target is at y = 70 in the branch's south-bound lane.
    private final Layout tee = Situations.tee();
    private final RoadNetwork network = RoadNetwork.of(tee);
    private final Route route = Route.plan(network, tee.target().orElseThrow());

    private Junction junction(int id) {
        return network.junctions().get(id);
    }

    @Test
    void theExitWhoseLaneLeadsToTheTargetIsTheDistanceAlongTheRoad() {
        assertEquals(40, route.distance(junction(0), Compass.SOUTH), 1e-9);
    }

    @Test
    void anExitAwayFromTheTargetCostsTheWayToTheDeadEndTheTurnAndTheWayBack() {
        double viaEastDeadEnd = 87 + Route.U_TURN_COST + 87 + 40;
        assertEquals(viaEastDeadEnd, route.distance(junction(0), Compass.EAST), 1e-9);
        assertEquals(viaEastDeadEnd, route.distance(junction(0), Compass.WEST), 1e-9);
    }

    @Test
    void comingUpTheTargetsRoadInTheOtherLaneMeansTurningRoundAtTheNextJunction() {
        assertEquals(57 + 40 + Route.U_TURN_COST, route.distance(junction(3), Compass.NORTH), 1e-9);
    }

    @Test
    void fromTheFarDeadEndTheWayRunsThroughTheTee() {
        assertEquals(87 + 40, route.distance(junction(2), Compass.WEST), 1e-9);
    }
}
