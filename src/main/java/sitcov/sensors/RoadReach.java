package sitcov.sensors;

import sitcov.geom.Rect;
import sitcov.world.RoadNetwork;

/**
 * How far a sensor ray stays on the road surface before its first gap: sensors' rays stop where
 * they leave the road. Gathers the roads near the sensor once per sweep, then answers per ray
 * without allocating.
 */
final class RoadReach {
    private static final int MAX_ROADS = 64;

    private RoadNetwork network;
    private Rect[] roads = new Rect[MAX_ROADS];
    private double[] interval = new double[2];
    private double[] start = new double[MAX_ROADS];
    private double[] end = new double[MAX_ROADS];
    private Rect[] holding = new Rect[MAX_ROADS];
    private int n;
    private int nHolding;

    RoadReach(RoadNetwork network) {
        this.network = network;
    }

    /** Keeps the road surfaces within {@code radius} of the sensor for the rays that follow. */
    void gather(double x, double y, double radius) {
        n = 0;
        nHolding = 0;
        for (Rect surface : network.surfaces()) {
            if (n < MAX_ROADS && surface.minX() <= x + radius && surface.maxX() >= x - radius
                    && surface.minY() <= y + radius && surface.maxY() >= y - radius) {
                roads[n++] = surface;
                if (surface.contains(x, y)) {
                    holding[nHolding++] = surface;
                }
            }
        }
    }

    /**
     * Whether the ray from the sensor at ({@code x}, {@code y}) along the unit vector reaches
     * {@code distance} metres without leaving the road. Cheap when one road holds both ends (a
     * road is convex), which is nearly always.
     */
    boolean reaches(double x, double y, double dx, double dy, double distance) {
        double hx = x + dx * distance;
        double hy = y + dy * distance;
        for (int k = 0; k < nHolding; k++) {
            if (holding[k].contains(hx, hy)) {
                return true;
            }
        }
        return along(x, y, dx, dy) + 1e-9 >= distance;
    }

    /** The distance along the unit ray from the sensor that the gathered roads cover without a gap. */
    double along(double x, double y, double dx, double dy) {
        int m = 0;
        for (int k = 0; k < n; k++) {
            if (roads[k].rayInterval(x, y, dx, dy, interval)) {
                start[m] = interval[0];
                end[m] = interval[1];
                m++;
            }
        }
        double reach = 0;
        boolean grew = true;
        while (grew) {
            grew = false;
            for (int k = 0; k < m; k++) {
                if (start[k] <= reach + 1e-9 && end[k] > reach) {
                    reach = end[k];
                    grew = true;
                }
            }
        }
        return reach;
    }
}
