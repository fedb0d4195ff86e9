package sitcov.builtin;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import sitcov.geom.Bearing;
import sitcov.geom.Box;
import sitcov.geom.Compass;
import sitcov.geom.Vec2;
import sitcov.vehicles.AutonomousCar;
import sitcov.vehicles.Body;
import sitcov.vehicles.CrossingPath;
import sitcov.vehicles.Dynamics;
import sitcov.vehicles.JunctionRules;
import sitcov.world.Dimensions;
import sitcov.world.Junction;
import sitcov.world.RoadNetwork;
import sitcov.world.Situations;

/**
 * Every way through a junction square keeps the autonomous car's whole body on the road and
 * leaves it in the exit lane, facing along it: the planned crossing paths fit the car.
 */
class JunctionTurnsTest {

    record Turn(String name, RoadNetwork network, Junction junction, Compass arrival, Compass exit) {
        @Override
        public String toString() {
            return name;
        }
    }

    static List<Turn> turns() {
        RoadNetwork tee = RoadNetwork.of(Situations.tee());
        Junction t = tee.junctions().get(0);
        Junction deadEnd = tee.junctions().get(3);
        List<Turn> turns = new ArrayList<>();
        // arriving on each arm of the tee, leaving by every arm (including back the way it came)
        for (Compass arm : t.arms()) {
            Compass arrival = arm.opposite();
            for (Compass exit : t.arms()) {
                turns.add(new Turn("tee from " + arm + " arm to " + exit, tee, t, arrival, exit));
            }
        }
        turns.add(new Turn("dead end U-turn", tee, deadEnd, Compass.SOUTH, Compass.NORTH));
        return turns;
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("turns")
    void theCarCrossesOnTheRoadAndLeavesAlignedInItsLane(Turn turn) {
        Junction j = turn.junction();
        double axle = AutonomousCar.REAR_AXLE;
        Compass arrival = turn.arrival();
        Compass exit = turn.exit();
        // the car's front at the square's edge, in the arrival lane
        Compass left = arrival.left();
        double x0 = j.centre().x() - arrival.dx() * Dimensions.HALF_ROAD + left.dx() * 1.5;
        double y0 = j.centre().y() - arrival.dy() * Dimensions.HALF_ROAD + left.dy() * 1.5;
        Vec2 wp = j.exitPoint(exit, JunctionRules.EXIT_BEYOND_SQUARE);
        CrossingPath path = CrossingPath.between(x0, y0, arrival, wp.x(), wp.y(), exit, j.centre().x(), j.centre().y(), axle);
        Body body = new Body(x0, y0, arrival.bearing(), axle);
        double speed = exit == arrival ? JunctionDriver.STRAIGHT_SPEED
                : exit == arrival.right() ? JunctionDriver.RIGHT_TURN_SPEED : exit == arrival.left() ? JunctionDriver.LEFT_TURN_SPEED : JunctionDriver.U_TURN_SPEED;
        for (int tick = 0; tick < 200; tick++) {
            path.turned(body.heading());
            double bearing = path.bearing(body.x(), body.y(), body.headingDx(), body.headingDy(), body.speed());
            double limit = path.isTurningOnTheSpot() ? 0
                    : Math.min(speed, Dynamics.speedToStopWithin(path.distanceToTurnOnTheSpot(body.x(), body.y(), body.headingDx(), body.headingDy())));
            body.approachSpeed(limit);
            body.turnTowards(bearing, Dynamics.MAX_TURN);
            body.move();
            Box footprint = Box.behind(body.x(), body.y(), body.heading(), 2, 2);
            assertTrue(turn.network().isOnRoad(footprint), "off the road at tick " + tick + ": " + footprint);
            double beyond = (body.x() - wp.x()) * exit.dx() + (body.y() - wp.y()) * exit.dy();
            if (beyond > CrossingPath.TAIL / 2) {
                double lateral = (body.x() - wp.x()) * exit.dy() - (body.y() - wp.y()) * exit.dx();
                assertTrue(Math.abs(lateral) < 0.3, "left the crossing " + lateral + " m off the lane centre");
                assertTrue(Math.abs(Bearing.turn(body.heading(), exit.bearing())) < 8,
                        "left the crossing heading " + body.heading());
                return;
            }
        }
        throw new AssertionError("never left the junction");
    }
}
