package sitcov.vehicles;

/**
 * What the car's behaviours ask for in one tick: a speed limit (the smallest wins), whether to
 * crawl, and a bearing to steer to (the first behaviour that steers wins).
 */
final class Intent {
    private double speedLimit;
    private boolean crawl;
    private double bearing;
    private String steeredBy;

    void reset() {
        speedLimit = Dynamics.MAX_SPEED;
        crawl = false;
        bearing = Double.NaN;
        steeredBy = null;
    }

    void limit(double speed) {
        speedLimit = Math.min(speedLimit, Math.max(0, speed));
    }

    /** Be able to stop within {@code distance} metres. */
    void stopWithin(double distance) {
        limit(Dynamics.speedToStopWithin(distance));
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
