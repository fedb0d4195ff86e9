package sitcov.vehicles;

import sitcov.control.Vehicle;
import sitcov.geom.Bearing;

/** How a moving car follows: the speed that keeps its stopping distance to whatever is in its path. */
final class Following {
    /** Vehicles whose anchor is further than this (squared, metres) are not in the path. */
    private static final double FOLLOW_RANGE_SQ = 46 * 46;

    private Following() {
    }

    /**
     * Keeps a stopping distance to any vehicle in its path (ground truth). After waiting long, an
     * impatient driver stops heeding other standing moving cars (their mishaps are not the system
     * under test's), which breaks gridlock; it always heeds the autonomous car.
     */
    static double limit(Scene scene, Vehicle self, Clearance clearance, boolean impatient) {
        double fx = self.headingDx();
        double fy = self.headingDy();
        // the speed to stop within a room grows with the room: the least room sets the limit
        double least = Double.POSITIVE_INFINITY;
        // the one pass over the traffic a step makes: it also tells the clearance check who is near
        clearance.clearNear();
        // nobody moves during the pass: the car's own place is read once
        double sx = self.x();
        double sy = self.y();
        Vehicle[] all = scene.vehicleArray();
        for (int each = 0; each < all.length; each++) {
            Vehicle other = all[each];
            if (other == self || !other.isActive()) {
                continue;
            }
            double ox = other.x() - sx;
            double oy = other.y() - sy;
            double distanceSq = ox * ox + oy * oy;
            clearance.vehicleAt(each, distanceSq);
            if (distanceSq > FOLLOW_RANGE_SQ || (impatient && other.speed() == 0 && other.id() != AutonomousCar.ID)) {
                continue;
            }
            // the other's centre lies within half its length of its anchor: an anchor that far behind
            // leaves the centre behind too, and the test below would skip it (saves the trigonometry)
            if (ox * fx + oy * fy < -other.length() / 2 - 1e-9) {
                continue;
            }
            double halfL = other.length() / 2;
            double cx = other.x() - halfL * other.headingDx() - sx;
            double cy = other.y() - halfL * other.headingDy() - sy;
            double u = cx * fx + cy * fy;
            double v = cx * fy - cy * fx;
            double corridor = 1.3;
            // the other's extent across is at most its half length plus half width: a car beyond
            // that is out of the path whatever its heading (saves the trigonometry)
            if (u < 0 || u > 40 || Math.abs(v) > halfL + other.width() / 2 + corridor) {
                continue;
            }
            double delta = other.heading() - self.heading();
            double cos = Bearing.cos(delta);
            double sin = Bearing.sin(delta);
            double extentU = Math.abs(cos) * halfL + Math.abs(sin) * other.width() / 2;
            double extentV = Math.abs(sin) * halfL + Math.abs(cos) * other.width() / 2;
            if (u < 0 || u > 40 || Math.abs(v) > extentV + corridor) {
                continue;
            }
            double gap = u - extentU;
            double lead = other.speed() * cos;
            double room = lead >= 0 ? gap + Dynamics.stoppingDistance(lead) - lead - MovingCar.GAP : gap - MovingCar.GAP + 4 * lead;
            least = Math.min(least, room);
        }
        return least == Double.POSITIVE_INFINITY ? Dynamics.MAX_SPEED
                : Math.min(Dynamics.MAX_SPEED, Dynamics.speedToStopWithin(least));
    }
}
