package sitcov.vehicles;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** The shared dynamics: stopping distances, their inverse, and how fast a car gets going. */
class DynamicsTest {

    @Test
    void theStoppingDistanceAtFullSpeedIsTheReferences() {
        // the original's stopping distance: sd = v + Σ_{k=0,1,…} (v − k·0.15625) while the term is positive.
        // At v = 2.5 the terms are positive for k = 0..15 (2.5 / 0.15625 = 16):
        // Σ = 16·2.5 − 0.15625·(0 + 1 + … + 15) = 40 − 0.15625·120 = 40 − 18.75 = 21.25,
        // sd = 2.5 + 21.25 = 23.75
        assertEquals(23.75, Dynamics.stoppingDistance(Dynamics.MAX_SPEED), 1e-9);
    }

    @Test
    void theStoppingDistanceIsWhatABrakingCarReallyTravelsPlusATickOfReaction() {
        // the reference counts the current speed once more than a braking car travels: checked
        // against the Body the cars drive, for every speed a car can reach (0.1 steps), which
        // rolls one tick, then brakes every tick until it stands
        for (int k = 0; k <= 25; k++) {
            Body body = new Body(0, 0, 90, 1.5);
            for (int i = 0; i < k; i++) {
                body.accelerate();
            }
            double v = body.speed();
            body.move();
            while (body.speed() > 0) {
                body.brake();
                body.move();
            }
            assertEquals(body.x() + v, Dynamics.stoppingDistance(v), 1e-9, "stopping distance from " + v);
        }
    }

    @Test
    void speedToStopWithinNeverGivesASpeedThatNeedsMoreRoomThanThat() {
        for (int i = 0; i <= 4000; i++) {
            double d = i * 0.01; // 0 .. 40 m
            double v = Dynamics.speedToStopWithin(d);
            assertTrue(v >= 0 && v <= Dynamics.MAX_SPEED, "speed " + v + " for " + d + " m");
            assertTrue(Dynamics.stoppingDistance(v) <= d + 1e-9,
                    "within " + d + " m it allows " + v + ", which needs " + Dynamics.stoppingDistance(v) + " m");
        }
    }

    @Test
    void withRoomForAFullSpeedStopFullSpeedIsAllowed() {
        double full = Dynamics.stoppingDistance(Dynamics.MAX_SPEED);
        assertEquals(Dynamics.MAX_SPEED, Dynamics.speedToStopWithin(full), 1e-12);
        assertEquals(Dynamics.MAX_SPEED, Dynamics.speedToStopWithin(full + 10), 1e-12);
        assertEquals(0, Dynamics.speedToStopWithin(0));
        assertEquals(0, Dynamics.speedToStopWithin(-3));
    }

    @Test
    void fromStandstillFullSpeedIsReachedInTwentyFiveTicks() {
        // 2.5 m/tick at +0.1 m/tick per tick: 2.5 / 0.1 = 25 ticks
        Body body = new Body(0, 0, 90, 1.5);
        for (int tick = 1; tick <= 24; tick++) {
            body.approachSpeed(Dynamics.MAX_SPEED);
            assertEquals(0.1 * tick, body.speed(), 1e-9, "speed after tick " + tick);
        }
        assertTrue(body.speed() < Dynamics.MAX_SPEED);
        body.approachSpeed(Dynamics.MAX_SPEED);
        assertEquals(Dynamics.MAX_SPEED, body.speed(), 1e-12);
        body.approachSpeed(Dynamics.MAX_SPEED);
        body.accelerate();
        assertEquals(Dynamics.MAX_SPEED, body.speed(), 1e-12, "never faster than full speed");
    }

    @Test
    void brakingFromFullSpeedTakesSixteenTicks() {
        // 2.5 / 0.15625 = 16 ticks, exactly (both are binary fractions)
        Body body = new Body(0, 0, 90, 1.5);
        for (int i = 0; i < 25; i++) {
            body.accelerate();
        }
        for (int tick = 1; tick <= 15; tick++) {
            body.brake();
            assertTrue(body.speed() > 0, "stopped after only " + tick + " ticks");
        }
        body.brake();
        assertEquals(0, body.speed());
    }

    @Test
    void slowingToATargetFollowsThePlainBisectionToTheBitAtEveryDistance() {
        double[] targets = {0, 0.3, 0.38, 0.5, 0.8, 1.0, 1.5, 2.0, 0.123};
        for (double target : targets) {
            for (double distance = -1; distance < 30; distance += 0.0137) {
                assertEquals(Double.doubleToRawLongBits(plainBisection(target, distance)),
                        Double.doubleToRawLongBits(Dynamics.speedToSlowTo(target, distance)),
                        "target " + target + ", distance " + distance);
            }
        }
    }

    @Test
    void slowingToATargetFollowsThePlainBisectionToTheBitRightAtEachDecisiveDistance() {
        // the distances where the answer changes are the slowing distances of the bisection's midpoints:
        // each of them, and the doubles either side, on every millimetre-a-tick speed
        double[] targets = {0, 0.38, 0.5, 1.0};
        for (double target : targets) {
            for (int mm = 0; mm <= 2500; mm++) {
                double at = slowing(mm * 0.001, target);
                for (double distance : new double[] {Math.nextDown(at), at, Math.nextUp(at)}) {
                    assertEquals(Double.doubleToRawLongBits(plainBisection(target, distance)),
                            Double.doubleToRawLongBits(Dynamics.speedToSlowTo(target, distance)),
                            "target " + target + ", distance " + distance);
                }
            }
        }
    }

    @Test
    void speedToStopWithinIsTheLastMillimetreATickThatStopsInTime() {
        // an independent statement: the largest k with stoppingDistance(k mm a tick) <= distance, tried at
        // each tabulated stopping distance, the doubles either side, and between them
        for (int mm = 0; mm <= 2500; mm++) {
            double at = Dynamics.stoppingDistance(mm * 0.001);
            for (double distance : new double[] {Math.nextDown(at), at, Math.nextUp(at), at + 0.0004}) {
                double expected;
                if (distance <= 0) {
                    expected = 0;
                } else if (distance >= Dynamics.stoppingDistance(Dynamics.MAX_SPEED)) {
                    expected = Dynamics.MAX_SPEED;
                } else {
                    int k = 0;
                    while (k + 1 <= 2500 && Dynamics.stoppingDistance((k + 1) * 0.001) <= distance) {
                        k++;
                    }
                    expected = k * 0.001;
                }
                assertEquals(Double.doubleToRawLongBits(expected), Double.doubleToRawLongBits(Dynamics.speedToStopWithin(distance)),
                        "distance " + distance);
            }
        }
    }

    /** The bisection as written before the tree: an independent statement of what speedToSlowTo must answer. */
    private static double plainBisection(double target, double distance) {
        if (distance <= 0 || target >= Dynamics.MAX_SPEED) {
            return Math.min(target, Dynamics.MAX_SPEED);
        }
        if (slowing(Dynamics.MAX_SPEED, target) <= distance) {
            return Dynamics.MAX_SPEED;
        }
        double lo = target;
        double hi = Dynamics.MAX_SPEED;
        while (hi - lo > 0.001) {
            double mid = (lo + hi) / 2;
            if (slowing(mid, target) <= distance) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        return lo;
    }

    private static double slowing(double from, double target) {
        double d = from;
        for (double v = from; v > target; v -= Dynamics.BRAKING) {
            d += v;
        }
        return d;
    }
}
