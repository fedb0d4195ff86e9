package sitcov.sensors;

import sitcov.geom.Bearing;

/**
 * The directions of a sensor's fan of rays, worked out once, each with its unit vector. A sensor
 * sweeps the same fan tick after tick (a lane's bearing is one of four), so it keeps the fans it
 * used ({@link Cache}) instead of paying two trigonometric calls a ray a tick. Each form computes
 * its angles by exactly the arithmetic its sensor used to do per ray, so every sample lands where
 * it did.
 */
final class RayFan {
    /** How the rays' angles are laid out. */
    enum Form {
        /** From {@code first} degrees left of the bearing down to {@code last}, {@code step} apart (the camera). */
        STEPPING_RIGHT,
        /** {@code first} rays, {@code step} degrees apart, starting {@code last} degrees right of the bearing (the LIDAR). */
        FROM_THE_RIGHT
    }

    private Form form;
    private double bearing;
    private double first;
    private double last;
    private double step;
    private double[] dx;
    private double[] dy;
    private double[] slope;
    private boolean sloped;
    private int slopedFrom;
    private int slopedTo;

    private RayFan(Form form, double bearing, double first, double last, double step) {
        this.form = form;
        this.bearing = bearing;
        this.first = first;
        this.last = last;
        this.step = step;
        int count = 0;
        if (form == Form.FROM_THE_RIGHT) {
            count = (int) first;
        } else {
            for (double i = first; i >= last - 1e-9; i -= step) {
                count++;
            }
        }
        dx = new double[count];
        dy = new double[count];
        slope = new double[count];
        double ahead = Bearing.dx(bearing);
        double aheadY = Bearing.dy(bearing);
        double i = first;
        for (int k = 0; k < count; k++) {
            double degrees;
            if (form == Form.FROM_THE_RIGHT) {
                degrees = bearing - last + k * step;
            } else {
                degrees = bearing + i;
                i -= step;
            }
            double r = Math.toRadians(degrees);
            dx[k] = Math.sin(r);
            dy[k] = Math.cos(r);
            // left over ahead, relative to the bearing; none for a ray square to it or behind
            double along = dx[k] * ahead + dy[k] * aheadY;
            double left = dx[k] * aheadY - dy[k] * ahead;
            slope[k] = along > 1e-6 ? left / along : Double.NaN;
        }
        int from = 0;
        while (from < count && Double.isNaN(slope[from])) {
            from++;
        }
        int to = from;
        while (to < count && !Double.isNaN(slope[to]) && (to == from || slope[to] < slope[to - 1])) {
            to++;
        }
        int after = to;
        while (after < count && Double.isNaN(slope[after])) {
            after++;
        }
        sloped = after == count;
        slopedFrom = from;
        slopedTo = to;
    }

    /**
     * Whether the rays with a slope are one run whose slopes strictly fall (rays square to the bearing
     * or behind it only before and after it): then the rays whose slope lies in an interval are a run
     * too, found by {@link #firstSlopeAtMost} and {@link #lastSlopeAtLeast}.
     */
    boolean slopesFall() {
        return sloped;
    }

    /** The first ray of the sloped run. */
    int slopedFrom() {
        return slopedFrom;
    }

    /** One past the last ray of the sloped run. */
    int slopedTo() {
        return slopedTo;
    }

    /** The first ray of the sloped run whose slope is at most {@code value} (the run's end if none); only when {@link #slopesFall}. */
    int firstSlopeAtMost(double value) {
        int lo = slopedFrom;
        int hi = slopedTo;
        while (lo < hi) {
            int mid = (lo + hi) >>> 1;
            if (slope[mid] <= value) {
                hi = mid;
            } else {
                lo = mid + 1;
            }
        }
        return lo;
    }

    /** The last ray of the sloped run whose slope is at least {@code value} (one before the run if none); only when {@link #slopesFall}. */
    int lastSlopeAtLeast(double value) {
        int lo = slopedFrom;
        int hi = slopedTo;
        while (lo < hi) {
            int mid = (lo + hi) >>> 1;
            if (slope[mid] >= value) {
                lo = mid + 1;
            } else {
                hi = mid;
            }
        }
        return lo - 1;
    }

    int size() {
        return dx.length;
    }

    /** The ray's sideways run per metre ahead, left positive, relative to the fan's bearing; NaN square to it or behind. */
    double slope(int ray) {
        return slope[ray];
    }

    double dx(int ray) {
        return dx[ray];
    }

    double dy(int ray) {
        return dy[ray];
    }

    private boolean is(Form f, double b, double fi, double l, double s) {
        return form == f && bearing == b && first == fi && last == l && step == s;
    }

    /** The few fans one sensor sweeps; a fan not kept is made and replaces the oldest. */
    static final class Cache {
        private RayFan[] fans;
        private int next;

        Cache(int size) {
            fans = new RayFan[size];
        }

        RayFan fan(Form form, double bearing, double first, double last, double step) {
            for (RayFan fan : fans) {
                if (fan != null && fan.is(form, bearing, first, last, step)) {
                    return fan;
                }
            }
            RayFan made = new RayFan(form, bearing, first, last, step);
            fans[next] = made;
            next = (next + 1) % fans.length;
            return made;
        }
    }
}
