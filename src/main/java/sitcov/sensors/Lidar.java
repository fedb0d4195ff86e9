package sitcov.sensors;

import java.util.List;
import sitcov.control.Vehicle;
import sitcov.geom.Bearing;
import sitcov.geom.Box;
import sitcov.geom.Compass;
import sitcov.geom.Rays;
import sitcov.world.Dimensions;
import sitcov.world.RoadNetwork;

/**
 * The obstacle LIDAR (faults/README.md, "The car under test, the traffic and the oracle"): 360 rays over
 * 180° at 0.5°, sampled every 0.5 m up to
 * 25 m. A ray stops at the first thing it hits — a parked car or a vehicle — so a car hidden
 * behind another is not seen, and at the first sample off the road. Hits are reported in the
 * lane frame: {@code u} metres ahead along the lane direction, {@code v} metres to its right.
 * Reuses its buffers: one LIDAR per car, not thread-safe.
 */
public final class Lidar {
    static final double ARC = 180;
    public static final double RANGE = 25;
    static final double ANGULAR_STEP = 0.5;
    static final double RANGE_STEP = 0.5;
    private static final int RAYS = (int) (ARC / ANGULAR_STEP);
    private static final int MAX_OBJECTS = 64;

    private Box[] objects = new Box[MAX_OBJECTS];
    private boolean[] objectParked = new boolean[MAX_OBJECTS];
    private double[] interval = new double[2];
    private int[] firstRay = new int[MAX_OBJECTS];
    private int[] lastRay = new int[MAX_OBJECTS];
    private RoadReach roadReach;
    /** Four lanes, and the heading fault 18 sweeps along. */
    private RayFan.Cache fans = new RayFan.Cache(6);

    /**
     * What the last full sweep looked at, and its hits, still in the buffers: parked cars never move
     * and a vehicle's footprint is a new object once it has moved, so a sweep from the same place, along
     * the same bearing and frame, over the same objects in the same order, sees the same.
     */
    private Snapshot swept = new Snapshot();
    private int sweptHits;

    /**
     * Per ray, the nearest sample on a parked car and whether the road reaches it, for the parked
     * cars of the place and bearing below: a car standing still (waiting, or stuck) sweeps the same
     * parked cars tick after tick while traffic passes, and only the traffic need be swept again.
     */
    private double[] parkedBest = new double[RAYS];
    private boolean[] parkedOnRoad = new boolean[RAYS];
    private Snapshot parkedSwept = new Snapshot();
    /** The span of rays the parked cars of {@link #parkedSwept} cover (empty: lowest above highest). */
    private int parkedLowest = RAYS;
    private int parkedHighest = -1;

    private double[] best = new double[RAYS];
    private boolean[] byVehicle = new boolean[RAYS];
    private double[] hitU = new double[RAYS];
    private double[] hitV = new double[RAYS];
    private boolean[] hitParked = new boolean[RAYS];
    private int hits;
    private double originX;
    private double originY;
    private Compass frame = Compass.NORTH;

    public Lidar(RoadNetwork network) {
        this.roadReach = new RoadReach(network);
    }

    /**
     * Sweeps around {@code centreBearing} from ({@code x}, {@code y}); hits are expressed in the
     * frame of {@code lane}. Returns the number of hits.
     */
    public int sweep(double x, double y, double centreBearing, Compass lane, List<Box> parkedBodies, List<Vehicle> vehicles,
              Vehicle self) {
        hits = 0;
        originX = x;
        originY = y;
        frame = lane;
        int n = 0;
        double reachSq = (RANGE + 5) * (RANGE + 5);
        double fx = Math.sin(Math.toRadians(centreBearing));
        double fy = Math.cos(Math.toRadians(centreBearing));
        for (int each = 0, count = parkedBodies.size(); each < count; each++) {
            Box body = parkedBodies.get(each);
            // the fan looks forward: a parked car wholly behind the sensor cannot be hit
            double ahead = (body.centreX() - x) * fx + (body.centreY() - y) * fy;
            if (n < MAX_OBJECTS && ahead > -Dimensions.CAR_LENGTH && distanceSq(body, x, y) <= reachSq) {
                objectParked[n] = true;
                objects[n++] = body;
            }
        }
        for (int each = 0, count = vehicles.size(); each < count; each++) {
            Vehicle v = vehicles.get(each);
            if (v != self && v.isActive() && n < MAX_OBJECTS
                    && (v.x() - x) * (v.x() - x) + (v.y() - y) * (v.y() - y) <= reachSq) {
                objectParked[n] = false;
                objects[n++] = v.footprint();
            }
        }
        if (n == 0) {
            return 0;
        }
        boolean anyParked = false;
        for (int k = 0; k < n && !anyParked; k++) {
            anyParked = objectParked[k];
        }
        if (!anyParked) {
            // moving cars matter to this sensor only as what hides parked cars
            return 0;
        }
        if (swept.matches(x, y, centreBearing, lane, objects, objectParked, n)) {
            hits = sweptHits;
            return hits;
        }
        // parked cars come first among the objects, and win a ray they tie on: sweep them, then the traffic
        int parked = 0;
        while (parked < n && objectParked[parked]) {
            parked++;
        }
        RayFan fan = fans.fan(RayFan.Form.FROM_THE_RIGHT, centreBearing, RAYS, ARC / 2, ANGULAR_STEP);
        roadReach.gather(x, y, RANGE);
        // the parked cars' rays are the same in any frame: the frame is left out of their snapshot
        if (!parkedSwept.matches(x, y, centreBearing, null, objects, objectParked, parked)) {
            sweepParked(x, y, centreBearing, parked, fan);
        }
        System.arraycopy(parkedBest, 0, best, 0, RAYS);
        java.util.Arrays.fill(byVehicle, false);
        // only the rays some object's span covers can have hit anything: the rest stay NaN and are skipped below
        int lowest = parkedLowest;
        int highest = parkedHighest;
        for (int k = parked; k < n; k++) {
            raysCovering(k, x, y, centreBearing);
            lowest = Math.min(lowest, firstRay[k]);
            highest = Math.max(highest, lastRay[k]);
            for (int ray = firstRay[k]; ray <= lastRay[k]; ray++) {
                double d = sample(k, x, y, fan, ray);
                if (!Double.isNaN(d) && (Double.isNaN(best[ray]) || d < best[ray])) {
                    best[ray] = d;
                    byVehicle[ray] = true;
                }
            }
        }
        Compass right = lane.right();
        Compass ahead = lane;
        for (int ray = lowest; ray <= highest; ray++) {
            if (Double.isNaN(best[ray])) {
                continue;
            }
            double dx = fan.dx(ray);
            double dy = fan.dy(ray);
            // the ray stops where it leaves the road; only a ray that hit something needs to know where
            if (byVehicle[ray] ? roadReach.reaches(x, y, dx, dy, best[ray]) : parkedOnRoad[ray]) {
                double hx = best[ray] * dx;
                double hy = best[ray] * dy;
                hitU[hits] = hx * ahead.dx() + hy * ahead.dy();
                hitV[hits] = hx * right.dx() + hy * right.dy();
                hitParked[hits] = !byVehicle[ray];
                hits++;
            }
        }
        swept.take(x, y, centreBearing, lane, objects, objectParked, n);
        sweptHits = hits;
        return hits;
    }

    /** The first sample of the ray on object {@code k}, or NaN. */
    private double sample(int k, double x, double y, RayFan fan, int ray) {
        if (!objects[k].rayInterval(x, y, fan.dx(ray), fan.dy(ray), interval)) {
            return Double.NaN;
        }
        return Rays.firstSample(interval[0], interval[1], 0, RANGE_STEP, RANGE);
    }

    /** Sweeps the first {@code parked} objects (the parked cars): the nearest sample per ray, the first car's on a tie. */
    private void sweepParked(double x, double y, double centreBearing, int parked, RayFan fan) {
        java.util.Arrays.fill(parkedBest, Double.NaN);
        parkedLowest = RAYS;
        parkedHighest = -1;
        for (int k = 0; k < parked; k++) {
            raysCovering(k, x, y, centreBearing);
            parkedLowest = Math.min(parkedLowest, firstRay[k]);
            parkedHighest = Math.max(parkedHighest, lastRay[k]);
            for (int ray = firstRay[k]; ray <= lastRay[k]; ray++) {
                double d = sample(k, x, y, fan, ray);
                if (!Double.isNaN(d) && (Double.isNaN(parkedBest[ray]) || d < parkedBest[ray])) {
                    parkedBest[ray] = d;
                }
            }
        }
        // outside the parked cars' spans parkedBest is NaN, and parkedOnRoad is never read
        for (int ray = parkedLowest; ray <= parkedHighest; ray++) {
            parkedOnRoad[ray] = !Double.isNaN(parkedBest[ray])
                    && roadReach.reaches(x, y, fan.dx(ray), fan.dy(ray), parkedBest[ray]);
        }
        parkedSwept.take(x, y, centreBearing, null, objects, objectParked, parked);
    }

    /**
     * The rays that can meet object {@code k}: those between the bearings of its corners. Only
     * saves work — a ray outside them cannot touch the box — so the sampled result is unchanged.
     */
    private void raysCovering(int k, double x, double y, double centreBearing) {
        double[] c = objects[k].corners();
        double lo = Double.MAX_VALUE;
        double hi = -Double.MAX_VALUE;
        for (int i = 0; i < 4; i++) {
            double t = Bearing.turn(centreBearing, Bearing.between(x, y, c[2 * i], c[2 * i + 1]));
            lo = Math.min(lo, t);
            hi = Math.max(hi, t);
        }
        if (hi - lo >= 180 || objects[k].contains(x, y)) {
            // the box wraps round the sensor (or holds it): every ray may meet it
            firstRay[k] = 0;
            lastRay[k] = RAYS - 1;
            return;
        }
        firstRay[k] = Math.max(0, (int) Math.floor((lo + ARC / 2) / ANGULAR_STEP) - 1);
        lastRay[k] = Math.min(RAYS - 1, (int) Math.ceil((hi + ARC / 2) / ANGULAR_STEP) + 1);
    }

    public int hits() {
        return hits;
    }

    public double u(int hit) {
        return hitU[hit];
    }

    public double v(int hit) {
        return hitV[hit];
    }

    /** Where the last sweep's hit {@code hit} lies in the world (for viewers). */
    public double worldX(int hit) {
        return originX + hitU[hit] * frame.dx() + hitV[hit] * frame.right().dx();
    }

    public double worldY(int hit) {
        return originY + hitU[hit] * frame.dy() + hitV[hit] * frame.right().dy();
    }

    public double originX() {
        return originX;
    }

    public double originY() {
        return originY;
    }

    public boolean isParkedCar(int hit) {
        return hitParked[hit];
    }

    private static double distanceSq(Box body, double x, double y) {
        double cx = body.centreX() - x;
        double cy = body.centreY() - y;
        return cx * cx + cy * cy;
    }

    /** Where a sweep was made from and what it looked at, object by object (by identity). */
    private static final class Snapshot {
        private Box[] objects = new Box[MAX_OBJECTS];
        private boolean[] parked = new boolean[MAX_OBJECTS];
        private int count = -1;
        private double x;
        private double y;
        private double bearing;
        private Compass frame;

        boolean matches(double atX, double atY, double along, Compass inFrame, Box[] seen, boolean[] seenParked, int n) {
            // places bit for bit (Double.compare tells −0 from 0): a sweep is reused only where it is certainly the same
            if (n != count || inFrame != frame || Double.compare(atX, x) != 0 || Double.compare(atY, y) != 0
                    || Double.compare(along, bearing) != 0) {
                return false;
            }
            for (int k = 0; k < n; k++) {
                if (seen[k] != objects[k] || seenParked[k] != parked[k]) {
                    return false;
                }
            }
            return true;
        }

        void take(double atX, double atY, double along, Compass inFrame, Box[] seen, boolean[] seenParked, int n) {
            System.arraycopy(seen, 0, objects, 0, n);
            System.arraycopy(seenParked, 0, parked, 0, n);
            count = n;
            x = atX;
            y = atY;
            bearing = along;
            frame = inFrame;
        }
    }
}
