package sitcov.sensors;

import java.util.List;
import sitcov.control.Vehicle;
import sitcov.geom.Bearing;
import sitcov.geom.Compass;

/**
 * The moving-vehicle sensor (a radar; faults/README.md, "The car under test, the traffic and the oracle"):
 * it sees vehicles up to 100 m away within
 * a forward field (45°, or 180° within 25 m), measures where they are and how fast they move, and
 * sorts them into those in the car's own path and those in the oncoming lane. Results are kept
 * in fields until the next scan; nothing is allocated.
 */
public final class TrafficSensor {
    static final double RANGE = 100;
    static final double NEAR_RANGE = 25;
    static final double FIELD = 45;
    /** Close by, the car sees all round (its mirrors): a car alongside or just behind is seen too. */
    static final double ALL_ROUND = 10;
    private static final double COS_HALF_FIELD = Math.cos(Math.toRadians(FIELD / 2));
    /** Half the corridor a 2 m car sweeps, plus a margin. */
    static final double PATH_HALF_WIDTH = 1.3;

    private double pathGap;
    private double pathSpeed;
    private double oncomingGap;
    private double oncomingSpeed;
    private double otherLaneGap;

    /**
     * Scans from the car {@code self} (from its anchor, along its heading), with the lane
     * running {@code lane} and its centre {@code laneCentre} metres to the car's right. Other-lane
     * vehicles between {@code fromU} and {@code toU} metres ahead mark the other lane occupied.
     */
    public void scan(List<Vehicle> vehicles, Vehicle self, Compass lane, double laneCentre, double fromU, double toU) {
        double x = self.x();
        double y = self.y();
        double heading = self.heading();
        pathGap = Double.POSITIVE_INFINITY;
        pathSpeed = 0;
        oncomingGap = Double.POSITIVE_INFINITY;
        oncomingSpeed = 0;
        otherLaneGap = Double.POSITIVE_INFINITY;
        double fx = lane.dx();
        double fy = lane.dy();
        double rx = lane.right().dx();
        double ry = lane.right().dy();
        // the path ahead is judged along the car's own heading (it may be turning); the lanes along the lane
        double hx = self.headingDx();
        double hy = self.headingDy();
        for (int each = 0, count = vehicles.size(); each < count; each++) {
            Vehicle other = vehicles.get(each);
            if (other == self || !other.isActive()) {
                continue;
            }
            double delta = other.heading() - lane.bearing();
            double cos = Bearing.cos(delta);
            double c = Math.abs(cos);
            double s = Math.abs(Bearing.sin(delta));
            double halfL = other.length() / 2;
            double halfW = other.width() / 2;
            double cx = other.x() - halfL * other.headingDx() - x;
            double cy = other.y() - halfL * other.headingDy() - y;
            double u = cx * fx + cy * fy;
            double v = cx * rx + cy * ry;
            double extentU = c * halfL + s * halfW;
            double extentV = s * halfL + c * halfW;
            double distance = Math.sqrt(cx * cx + cy * cy);
            if (distance > RANGE + extentU || !inField(cx, cy, heading, hx, hy, distance)) {
                continue;
            }
            double along = other.speed() * cos;
            double gap = u - extentU;
            double headingDelta = other.heading() - heading;
            double headingCos = Bearing.cos(headingDelta);
            double pc = Math.abs(headingCos);
            double ps = Math.abs(Bearing.sin(headingDelta));
            double pathU = cx * hx + cy * hy;
            double pathV = cx * hy - cy * hx;
            double pathGapHere = pathU - (pc * halfL + ps * halfW);
            if (pathGapHere > -1 && Math.abs(pathV) < ps * halfL + pc * halfW + PATH_HALF_WIDTH && pathGapHere < pathGap) {
                pathGap = Math.max(0, pathGapHere);
                pathSpeed = other.speed() * headingCos;
            }
            boolean inOtherLane = v + extentV > laneCentre + 1.6 && v - extentV < laneCentre + 4.4;
            if (inOtherLane) {
                if (u + extentU > fromU && gap < toU) {
                    otherLaneGap = Math.min(otherLaneGap, Math.max(0, gap));
                }
                if (along < 0.05 && gap > -2 && gap < oncomingGap) {
                    oncomingGap = Math.max(0, gap);
                    oncomingSpeed = -along;
                }
            }
        }
    }

    /**
     * Whether the point ({@code cx}, {@code cy}) from the sensor lies in the field of a sensor
     * facing {@code heading} (unit vector {@code hx}, {@code hy}). The angle off the heading is
     * judged by its cosine, and only a point within a hair of the field's edge is judged by the
     * bearings themselves, which decide there exactly as they always did.
     */
    private static boolean inField(double cx, double cy, double heading, double hx, double hy, double distance) {
        if (distance <= ALL_ROUND) {
            return true;
        }
        boolean near = distance <= NEAR_RANGE;
        double half = near ? 90 : FIELD / 2;
        double edge = near ? 0 : COS_HALF_FIELD;
        double cosine = (cx * hx + cy * hy) / distance;
        if (Math.abs(cosine - edge) > 1e-9) {
            return cosine > edge;
        }
        return Math.abs(Bearing.turn(heading, Bearing.between(0, 0, cx, cy))) <= half;
    }

    /** Distance to the nearest vehicle in the car's path (infinite if none). */
    public double pathGap() {
        return pathGap;
    }

    /** That vehicle's speed along the lane direction (negative when it comes towards the car). */
    public double pathSpeed() {
        return pathSpeed;
    }

    /** Distance to the nearest vehicle coming the other way in the oncoming lane. */
    public double oncomingGap() {
        return oncomingGap;
    }

    /** Its speed towards the car. */
    public double oncomingSpeed() {
        return oncomingSpeed;
    }

    /** Distance to the nearest vehicle of any direction in the other lane, from just behind the car on (infinite if none). */
    public double otherLaneGap() {
        return otherLaneGap;
    }
}
