package sitcov.builtin;

import sitcov.vehicles.Dynamics;

/**
 * What the car's behaviours ask for in one tick: a speed limit (the smallest wins), whether to
 * crawl, and a bearing to steer to (the first behaviour that steers wins).
 */
final class Intent {
    private double speedLimit;
    private String limitedBy;
    private boolean crawl;
    private double bearing;
    private String steeredBy;

    void reset() {
        speedLimit = Dynamics.MAX_SPEED;
        limitedBy = null;
        crawl = false;
        bearing = Double.NaN;
        steeredBy = null;
    }

    void limit(double speed, String by) {
        double s = Math.max(0, speed);
        if (s < speedLimit) {
            speedLimit = s;
            limitedBy = by;
        }
    }

    /** Be able to stop within {@code distance} metres. */
    void stopWithin(double distance, String by) {
        limit(Dynamics.speedToStopWithin(distance), by);
    }

    /** Which behaviour set the speed limit in force (null when none did). */
    String limitedBy() {
        return limitedBy;
    }

    void crawl() {
        crawl = true;
    }

    boolean steer(double newBearing, String by) {
        if (Double.isNaN(bearing)) {
            bearing = newBearing;
            steeredBy = by;
            return true;
        }
        return false;
    }

    boolean hasBearing() {
        return !Double.isNaN(bearing);
    }

    double speedLimit() {
        return speedLimit;
    }

    boolean isCrawl() {
        return crawl;
    }

    double bearing() {
        return bearing;
    }

    String steeredBy() {
        return steeredBy;
    }
}
