package sitcov.builtin;

import sitcov.faults.Fault;
import sitcov.faults.FaultSwitchboard;
import sitcov.geom.Bearing;
import sitcov.geom.Compass;
import sitcov.sensors.Lidar;

/**
 * What the overtaking car reads off its LIDAR about parked cars, in the frame of its lane: the row
 * ahead in its lane, cars parked on the other side, and whether one stands in its way. Fault 18
 * (the obstacle search along the heading) acts here.
 */
final class ParkedCarSightings {
    /** Half the width the car sweeps, with a margin: a parked car inside it is in the car's way. */
    static final double CORRIDOR = 1.15;
    /** A car parked on the other side less than this far behind the car's front still stands beside it. */
    static final double BESIDE = 2.5;

    private BuiltinCar car;
    private FaultSwitchboard faults;

    ParkedCarSightings(BuiltinCar car, FaultSwitchboard faults) {
        this.car = car;
        this.faults = faults;
    }

    /** What the LIDAR shows of parked cars, in the lane frame. */
    record Sighting(double nearest, double farthest, double opposite, boolean oppositeBeside) {
    }

    /** Sweeps along {@code lane} and reads the parked cars ahead and on the other side. */
    Sighting look(Compass lane, double laneCentre) {
        Lidar lidar = car.lidar();
        if (!faults.watches(Fault.OBSTACLE_SEARCH_ALONG_HEADING)) {
            return alongLane(lidar, lane, laneCentre);
        }
        // the faulty car takes the road to run along its heading: hits are read in the heading's frame
        int hits = lidar.sweep(car.x(), car.y(), car.heading(), lane, car.obstacles(), car.trafficTracks(), car);
        Sighting faulty = sighting(lidar, laneCentre, Math.toRadians(Bearing.turn(lane.bearing(), car.heading())));
        if (hits > 0 && !faulty.equals(sighting(lidar, laneCentre, 0))) {
            faults.effective(Fault.OBSTACLE_SEARCH_ALONG_HEADING);
        } else {
            faults.reached(Fault.OBSTACLE_SEARCH_ALONG_HEADING);
        }
        if (faults.isActive(Fault.OBSTACLE_SEARCH_ALONG_HEADING)) {
            return faulty;
        }
        // watched from the shadows: the lidar is left as the fault-free car leaves it. Only what it
        // read departs: nothing but this reading (and a viewer's drawing) uses the car's last sweep,
        // and the lidar's memory of a sweep gives what a fresh sweep would
        Sighting correct = alongLane(lidar, lane, laneCentre);
        if (!faulty.equals(correct)) {
            faults.departs(Fault.OBSTACLE_SEARCH_ALONG_HEADING);
        }
        return correct;
    }

    private Sighting alongLane(Lidar lidar, Compass lane, double laneCentre) {
        lidar.sweep(car.x(), car.y(), lane.bearing(), lane, car.obstacles(), car.trafficTracks(), car);
        return sighting(lidar, laneCentre, 0);
    }

    /** Parked cars in the lane ahead and on the other side, with the hits turned by {@code phi} first. */
    private static Sighting sighting(Lidar lidar, double laneCentre, double phi) {
        double cos = Math.cos(phi);
        double sin = Math.sin(phi);
        double nearest = Double.NaN;
        double farthest = Double.NaN;
        double opposite = Double.NaN;
        boolean beside = false;
        for (int h = 0; h < lidar.hits(); h++) {
            if (!lidar.isParkedCar(h)) {
                continue;
            }
            double u = lidar.u(h) * cos - lidar.v(h) * sin;
            double v = lidar.u(h) * sin + lidar.v(h) * cos;
            if (u > 0 && v > laneCentre - 1.4 && v < laneCentre + 1.4) {
                nearest = Double.isNaN(nearest) ? u : Math.min(nearest, u);
                farthest = Double.isNaN(farthest) ? u : Math.max(farthest, u);
            } else if (u > -BESIDE && v > laneCentre + 1.6 && v < laneCentre + 4.4) {
                if (u > 1) {
                    opposite = Double.isNaN(opposite) ? u : Math.min(opposite, u);
                } else {
                    beside = true;
                }
            }
        }
        return new Sighting(nearest, farthest, opposite, beside);
    }

    /** Whether no parked car stands in the car's own lane from just behind it to a few metres ahead (last sweep). */
    boolean ownLaneFreeBeside(double laneCentre) {
        Lidar lidar = car.lidar();
        for (int h = 0; h < lidar.hits(); h++) {
            if (lidar.isParkedCar(h) && lidar.u(h) > -BuiltinCar.REAR_AXLE - 1
                    && lidar.u(h) < Overtaker.PULL_IN_AHEAD + 1 && Math.abs(lidar.v(h) - laneCentre) < 1.5) {
                return false;
            }
        }
        return true;
    }

    /** The farthest hit of the last sweep on a parked car in the car's lane between it and {@code before} metres ahead, or NaN. */
    double farthestParkedBefore(double before, double laneCentre) {
        return farthestParkedBefore(before, laneCentre, 0);
    }

    double farthestParkedBefore(double before, double laneCentre, double from) {
        Lidar lidar = car.lidar();
        double farthest = Double.NaN;
        for (int h = 0; h < lidar.hits(); h++) {
            double u = lidar.u(h);
            if (lidar.isParkedCar(h) && u > from && u < before && Math.abs(lidar.v(h) - laneCentre) < 1.4) {
                farthest = Double.isNaN(farthest) ? u : Math.max(farthest, u);
            }
        }
        return farthest;
    }

    /** Sweeps again: the distance to the nearest parked car inside the width the car sweeps ahead of it, or NaN. */
    double parkedCarInTheWay(Compass lane) {
        Lidar lidar = car.lidar();
        int hits = lidar.sweep(car.x(), car.y(), lane.bearing(), lane, car.obstacles(), car.trafficTracks(), car);
        // the width the car sweeps lies along its heading, which pulling out turns away from the lane
        double phi = Math.toRadians(Bearing.turn(lane.bearing(), car.heading()));
        double cos = Math.cos(phi);
        double sin = Math.sin(phi);
        double nearest = Double.NaN;
        for (int h = 0; h < hits; h++) {
            double along = lidar.u(h) * cos - lidar.v(h) * sin;
            double across = lidar.u(h) * sin + lidar.v(h) * cos;
            if (lidar.isParkedCar(h) && along > 0 && Math.abs(across) < CORRIDOR) {
                nearest = Double.isNaN(nearest) ? along : Math.min(nearest, along);
            }
        }
        return nearest;
    }
}
