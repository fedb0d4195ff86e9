package sitcov.seam;

import java.util.List;
import sitcov.control.Channel;
import sitcov.control.Observation;
import sitcov.control.RightOfWay;
import sitcov.control.Vehicle;
import sitcov.geom.Box;

/**
 * Whether a distorted observation hands a controller another value than the real one, on the parts
 * it read: exact comparison, number for number, as a replay would need them to be the same.
 */
final class Sameness {
    private Sameness() {
    }

    /** Whether {@code seen} differs from {@code real} in a part of {@code parts} that {@code read} says was read. */
    static boolean differs(Observation seen, Observation real, int parts, Consults read) {
        int mask = read.mask() & parts;
        if (Part.has(mask, Part.POSE) && (ne(seen.x(), real.x()) || ne(seen.y(), real.y())
                || ne(seen.heading(), real.heading()) || ne(seen.speed(), real.speed()))) {
            return true;
        }
        if (Part.has(mask, Part.TRAFFIC) && !sameTraffic(seen.traffic(), real.traffic())) {
            return true;
        }
        if (Part.has(mask, Part.OBSTACLES) && !sameObstacles(seen.obstacles(), real.obstacles())) {
            return true;
        }
        if (Part.has(mask, Part.CAMERA) && !sameCamera(seen, real)) {
            return true;
        }
        if (Part.has(mask, Part.LIDAR) && !sameLidar(seen, real)) {
            return true;
        }
        if (Part.has(mask, Part.RIGHT_OF_WAY) && !sameSignals(seen.rightOfWay(), real.rightOfWay(), read)) {
            return true;
        }
        for (Channel c : Channel.values()) {
            if (Part.has(mask, Part.channel(c)) && ne(seen.channel(c), real.channel(c))) {
                return true;
            }
        }
        return false;
    }

    private static boolean ne(double a, double b) {
        return Double.compare(a, b) != 0;
    }

    private static boolean sameTraffic(List<Vehicle> a, List<Vehicle> b) {
        if (a.size() != b.size()) {
            return false;
        }
        for (int i = 0, n = a.size(); i < n; i++) {
            Vehicle u = a.get(i);
            Vehicle v = b.get(i);
            if (u.id() != v.id() || ne(u.x(), v.x()) || ne(u.y(), v.y()) || ne(u.heading(), v.heading())
                    || ne(u.speed(), v.speed()) || ne(u.length(), v.length()) || ne(u.width(), v.width())) {
                return false;
            }
        }
        return true;
    }

    private static boolean sameObstacles(List<Box> a, List<Box> b) {
        if (a.size() != b.size()) {
            return false;
        }
        for (int i = 0, n = a.size(); i < n; i++) {
            Box u = a.get(i);
            Box v = b.get(i);
            if (u != v && (ne(u.centreX(), v.centreX()) || ne(u.centreY(), v.centreY()) || ne(u.bearing(), v.bearing())
                    || ne(u.length(), v.length()) || ne(u.width(), v.width()))) {
                return false;
            }
        }
        return true;
    }

    private static boolean sameCamera(Observation a, Observation b) {
        int n = a.cameraHits();
        if (n != b.cameraHits()) {
            return false;
        }
        for (int h = 0; h < n; h++) {
            if (ne(a.cameraHitX(h), b.cameraHitX(h)) || ne(a.cameraHitY(h), b.cameraHitY(h))) {
                return false;
            }
        }
        return true;
    }

    private static boolean sameLidar(Observation a, Observation b) {
        int n = a.lidarHits();
        if (n != b.lidarHits()) {
            return false;
        }
        for (int h = 0; h < n; h++) {
            if (ne(a.lidarHitX(h), b.lidarHitX(h)) || ne(a.lidarHitY(h), b.lidarHitY(h))) {
                return false;
            }
        }
        return true;
    }

    private static boolean sameSignals(RightOfWay a, RightOfWay b, Consults read) {
        for (int i = 0; i < read.askedCount(); i++) {
            int j = read.askedAt(i);
            if (a.holds(j) != b.holds(j) || a.wouldGrant(j) != b.wouldGrant(j)) {
                return false;
            }
        }
        return true;
    }
}
