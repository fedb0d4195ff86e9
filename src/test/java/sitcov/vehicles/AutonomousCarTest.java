package sitcov.vehicles;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.function.BiConsumer;
import org.junit.jupiter.api.Test;
import sitcov.control.Channel;
import sitcov.control.Command;
import sitcov.control.ControllerFactory;
import sitcov.control.Observation;
import sitcov.engine.SimState;
import sitcov.geom.Compass;
import sitcov.geom.Vec2;
import sitcov.world.Situations;
import sitcov.world.StartPose;
import sitcov.world.WorldMap;

/** The world's side of the seam: what it hands a controller, and what it makes of the command. */
class AutonomousCarTest {
    private static Scene scene(WorldMap map, BiConsumer<Observation, Command> controller) {
        SimState state = new SimState(1);
        ControllerFactory factory = run -> controller::accept;
        return Scene.start(map, state, factory);
    }

    @Test
    void aCommandBeyondTheCarsLimitsIsClampedAndTheClampingRecorded() {
        Scene scene = scene(Situations.withoutTraffic(Situations.straight(List.of())),
                (now, out) -> out.speedChange(10).steering(90));
        AutonomousCar car = scene.autonomousCar();
        double heading = car.heading();
        scene.state().step();
        assertEquals(Dynamics.MAX_SPEED, car.speed(), 0.0, "10 m a tick is clamped to 2.5");
        assertEquals(heading + Dynamics.MAX_TURN, car.heading(), 1e-9, "90° is clamped to 15°");
        assertTrue(car.wasClamped());
        assertEquals(1, car.clampedTicks());
        assertEquals(Dynamics.MAX_SPEED, scene.telemetry().speedChange(), 0.0, "the telemetry has what was carried out");
    }

    @Test
    void aCommandWithinTheLimitsIsCarriedOutAsGiven() {
        Scene scene = scene(Situations.withoutTraffic(Situations.straight(List.of())),
                (now, out) -> out.speedChange(0.1).steering(-2));
        AutonomousCar car = scene.autonomousCar();
        scene.state().step();
        scene.state().step();
        assertEquals(0.2, car.speed(), 1e-12);
        assertEquals(90 - 4, car.heading(), 1e-9);
        assertFalse(car.wasClamped());
    }

    @Test
    void aControllerSeesOtherVehiclesOnlyWithinSensorRangeAndNeverItself() {
        // the car starts at x = 40; one moving car 30 m ahead, one 130 m ahead (beyond 80 m)
        WorldMap map = Situations.withTraffic(Situations.straight(List.of()),
                List.of(new StartPose(new Vec2(70, 51.5), Compass.WEST), new StartPose(new Vec2(170, 51.5), Compass.WEST)));
        List<Integer> seen = new ArrayList<>();
        Scene scene = scene(map, (now, out) -> {
            if (now.tick() == 0) {
                now.traffic().forEach(v -> seen.add(v.id()));
            }
        });
        scene.state().step();
        assertEquals(List.of(1), seen);
    }

    @Test
    void groundTruthChannelsMeasureTheCarsPlaceInItsLane() {
        // east-bound lane centre y = 48.5; the car starts on it, facing east; right of east is +y
        double[] offset = new double[3];
        Scene scene = scene(Situations.withoutTraffic(Situations.straight(List.of())), (now, out) -> {
            if (now.tick() == 0) {
                offset[0] = now.channel(Channel.LANE_OFFSET);
                offset[1] = now.channel(Channel.HEADING_ERROR);
                offset[2] = now.channel(Channel.TARGET_DISTANCE);
            }
        });
        scene.state().step();
        assertEquals(0, offset[0], 1e-9);
        assertEquals(0, offset[1], 1e-9);
        assertEquals(150 - 40, offset[2], 1e-9, "the Target lies 110 m ahead");
    }

    @Test
    void aJunctionAskedForIsGivenOnlyWhenItsSignalSaidSo() {
        // junction 1, the dead end behind the start, is within the 30 m a claim may be made from
        WorldMap map = Situations.withoutTraffic(Situations.tee());
        boolean[] signalled = new boolean[2];
        Scene scene = scene(map, (now, out) -> {
            signalled[(int) now.tick()] = now.rightOfWay().wouldGrant(1);
            out.claim(1);
        });
        scene.occupancy().request(1, 99, 0, 0);
        scene.state().step();
        assertFalse(signalled[0], "another vehicle holds junction 1");
        assertFalse(scene.occupancy().isHeldBy(1, AutonomousCar.ID));
        scene.occupancy().release(1, 99);
        scene.state().step();
        assertTrue(signalled[1]);
        assertTrue(scene.occupancy().isHeldBy(1, AutonomousCar.ID), "once free it is given");
    }
}
