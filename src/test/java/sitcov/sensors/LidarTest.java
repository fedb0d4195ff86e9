package sitcov.sensors;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import sitcov.control.Vehicle;
import sitcov.geom.Box;
import sitcov.geom.Compass;
import sitcov.geom.Vec2;
import sitcov.world.Axis;
import sitcov.world.Dimensions;
import sitcov.world.Layout;
import sitcov.world.ParkedCar;
import sitcov.world.Road;
import sitcov.world.RoadNetwork;
import sitcov.world.Situations;

/**
 * The LIDAR on the straight road, sweeping from the east-bound lane centre (x = 40, y = 48.5)
 * around east. A parked car in that lane centred at x occupies x ± 2.5 and y ∈ [47.325, 49.325]
 * (centre y = 50 − 1.675), i.e. v ∈ [−1.175, 0.825] in the lane frame of the sensor.
 *
 * <p>A hit is the first sample inside an object, so every hit point lies inside the object hit.
 */
class LidarTest {
    private static final double X = 40;
    private static final double Y = 48.5;
    private static final double EPS = 1e-6;

    @Test
    void aParkedCarAheadIsSeenFirstAtItsRearFace() {
        // centred at x = 55: its rear face is at x = 52.5, 12.5 m ahead; the straight-ahead ray
        // (bearing 90, the 181st) samples 12.5 m exactly, and no hit can be nearer than the face
        Lidar lidar = sweep(List.of(Situations.parkedInEastboundLane(0, 55)));

        assertTrue(lidar.hits() > 0, "the parked car was not seen");
        double nearest = Double.MAX_VALUE;
        for (int i = 0; i < lidar.hits(); i++) {
            assertTrue(lidar.isParkedCar(i), "hit " + i + " is not on a parked car");
            // every hit lies on the car: u ∈ [12.5, 17.5], v ∈ [−1.175, 0.825]
            assertTrue(lidar.u(i) >= 12.5 - EPS && lidar.u(i) <= 17.5 + EPS, "u " + lidar.u(i));
            assertTrue(lidar.v(i) >= -1.175 - EPS && lidar.v(i) <= 0.825 + EPS, "v " + lidar.v(i));
            nearest = Math.min(nearest, lidar.u(i));
        }
        // within one 0.5 m sample of the rear face
        assertTrue(nearest >= 12.5 - EPS && nearest <= 12.5 + 0.5, "nearest hit at " + nearest);
    }

    @Test
    void aSecondParkedCarHiddenBehindTheFirstIsNotSeen() {
        // first car x ∈ [52.5, 57.5], second (8 m further) x ∈ [60.5, 65.5], both y ∈ [47.325, 49.325].
        // The sensor is inside that band, so the segment from it to any point of the second car
        // stays in the band and crosses the whole first car: at least 5 m of it, which holds
        // samples, all nearer than the second car. So no hit lies beyond the first car's front.
        Lidar lidar = sweep(List.of(Situations.parkedInEastboundLane(0, 55), Situations.parkedInEastboundLane(1, 63)));

        assertTrue(lidar.hits() > 0);
        for (int i = 0; i < lidar.hits(); i++) {
            assertTrue(lidar.u(i) <= 17.5 + EPS, "hit " + i + " at u = " + lidar.u(i) + " is beyond the first car");
        }
    }

    @Test
    void theSecondParkedCarAloneIsSeen() {
        // the control for the occlusion test: its rear face is 20.5 m ahead, within 25 m
        Lidar lidar = sweep(List.of(Situations.parkedInEastboundLane(1, 63)));

        assertTrue(lidar.hits() > 0);
        assertEquals(20.5, nearestU(lidar), 0.5 + EPS);
        assertTrue(nearestU(lidar) >= 20.5 - EPS);
    }

    @Test
    void aParkedCarBeyondTwentyFiveMetresIsNotSeen() {
        // centred at x = 68 (centre 28 m away, so it is a candidate), rear face at x = 65.5:
        // every point of it is at least 25.5 m away, beyond the last sample at 25 m
        Lidar lidar = sweep(List.of(Situations.parkedInEastboundLane(0, 68)));

        assertEquals(0, lidar.hits());
    }

    @Test
    void nothingBehindTheCarIsSeen() {
        // the 180° fan runs from bearing 0 (south) to 179.5 (just east of north): every ray has
        // dx = sin(bearing) ≥ 0, so none reaches the car behind, x ∈ [27.5, 32.5]
        Lidar behindOnly = sweep(List.of(Situations.parkedInEastboundLane(0, 30)));
        assertEquals(0, behindOnly.hits());

        Lidar both = sweep(List.of(Situations.parkedInEastboundLane(0, 30), Situations.parkedInEastboundLane(1, 55)));
        assertTrue(both.hits() > 0, "the car ahead was not seen");
        for (int i = 0; i < both.hits(); i++) {
            assertTrue(both.u(i) > 0, "hit behind the car at u = " + both.u(i));
        }
    }

    @Test
    void raysStopWhereTheRoadEndsSoAParkedCarBeyondAGapIsNotSeen() {
        // road A ends at x = 100, road B starts at 101; from x = 95 a parked car on B centred at
        // 110 has its rear face 12.5 m ahead, but every ray leaves A's surface by x = 100
        ParkedCar onB = new ParkedCar(0, 1, new Vec2(110, 48.325), Axis.EAST_WEST);

        assertEquals(0, sweepFrom(95, twoRoads(101, onB)).hits());
        // the control: with no gap it is seen, first at its rear face
        Lidar noGap = sweepFrom(95, twoRoads(100, onB));
        assertTrue(noGap.hits() > 0);
        assertEquals(12.5, nearestU(noGap), 0.5 + EPS);
    }

    @Test
    void aLidarStandingStillSweepsAsAFreshOneWhenTrafficComesBetweenItsSweeps() {
        // it remembers its parked cars' rays while it stands still: traffic arriving in front must still count
        Layout layout = Situations.straight(List.of(Situations.parkedInEastboundLane(0, 63)));
        RoadNetwork network = RoadNetwork.of(layout);
        List<Box> parked = parkedBodies(layout);
        Lidar standing = new Lidar(network);
        int before = standing.sweep(X, Y, Compass.EAST.bearing(), Compass.EAST, parked, List.of(), null);
        assertTrue(before > 0 && parkedHits(standing) == before, "the parked car alone, 20.5 m ahead, is seen");

        // a moving car stands 5 to 10 m ahead in the same lane, between the sensor and the parked car
        List<Vehicle> traffic = List.of(new CarAt(50, Y, Compass.EAST.bearing()));
        int after = standing.sweep(X, Y, Compass.EAST.bearing(), Compass.EAST, parked, traffic, null);
        Lidar fresh = new Lidar(network);
        assertEquals(fresh.sweep(X, Y, Compass.EAST.bearing(), Compass.EAST, parked, traffic, null), after);
        for (int i = 0; i < after; i++) {
            assertEquals(fresh.u(i), standing.u(i), 0, "hit " + i);
            assertEquals(fresh.v(i), standing.v(i), 0, "hit " + i);
            assertEquals(fresh.isParkedCar(i), standing.isParkedCar(i), "hit " + i);
        }
        assertTrue(after > parkedHits(standing), "the moving car is hit");
        assertTrue(parkedHits(standing) < before, "and hides part of the parked car");
    }

    private static int parkedHits(Lidar lidar) {
        int parked = 0;
        for (int i = 0; i < lidar.hits(); i++) {
            parked += lidar.isParkedCar(i) ? 1 : 0;
        }
        return parked;
    }

    private static Lidar sweep(List<ParkedCar> parked) {
        return sweepFrom(X, Situations.straight(parked));
    }

    private static Lidar sweepFrom(double x, Layout layout) {
        Lidar lidar = new Lidar(RoadNetwork.of(layout));
        int hits = lidar.sweep(x, Y, Compass.EAST.bearing(), Compass.EAST, parkedBodies(layout), List.of(), null);
        assertEquals(hits, lidar.hits());
        return lidar;
    }

    private static List<Box> parkedBodies(Layout layout) {
        return layout.parkedCars().stream().map(ParkedCar::footprint).toList();
    }

    /** A car of the traffic standing still, as the radar reports it. */
    private record CarAt(double x, double y, double heading) implements Vehicle {
        @Override
        public int id() {
            return 1;
        }

        @Override
        public double speed() {
            return 0;
        }

        @Override
        public double length() {
            return Dimensions.CAR_LENGTH;
        }

        @Override
        public double width() {
            return Dimensions.CAR_WIDTH;
        }

        @Override
        public boolean isActive() {
            return true;
        }
    }

    private static double nearestU(Lidar lidar) {
        double nearest = Double.MAX_VALUE;
        for (int i = 0; i < lidar.hits(); i++) {
            nearest = Math.min(nearest, lidar.u(i));
        }
        return nearest;
    }

    private static Layout twoRoads(double bStart, ParkedCar parked) {
        return Situations.layout(
                List.of(new Road(0, Axis.EAST_WEST, 50, 20, 100), new Road(1, Axis.EAST_WEST, 50, bStart, 180)),
                List.of(), List.of(parked), null, null);
    }
}
