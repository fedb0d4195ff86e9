package sitcov.vehicles;

import sitcov.geom.Compass;
import sitcov.geom.Rays;
import sitcov.geom.Rect;
import sitcov.world.Marking;
import sitcov.world.MarkingKind;
import sitcov.world.RoadNetwork;

/**
 * The road-marking camera: sampled rays fanned out from the car's front centre around the lane
 * direction, the left sector looking for the kerb-side edge line and the right sector for the
 * centre line. A ray reports the first sample that falls on a painted strip, and stops where it
 * leaves the road. Which samples hit is computed exactly from each ray's interval across each
 * strip, so the sampled semantics (and what coarser sampling misses) are kept without marching.
 * Reuses its buffers: one camera per car, not thread-safe.
 */
final class MarkingCamera {
    private static final int MAX_CANDIDATES = 64;

    private final RoadNetwork network;
    private final Rect[] strips = new Rect[MAX_CANDIDATES];
    private final double[] interval = new double[2];
    private final RoadReach roadReach;

    MarkingCamera(RoadNetwork network) {
        this.network = network;
        this.roadReach = new RoadReach(network);
    }

    /** Looks from ({@code x}, {@code y}) around {@code lane} and estimates where the lane is. */
    LaneEstimate look(double x, double y, Compass lane, CameraSettings settings) {
        double limit = settings.limit();
        roadReach.gather(x, y, limit);
        Compass right = lane.right();
        double edgeSum = 0;
        int edgeHits = 0;
        int n = nearbyStrips(x, y, lane, limit, MarkingKind.EDGE);
        for (double i = settings.leftArc(); i >= -1e-9; i -= settings.angularStep()) {
            double v = lateralOfHit(x, y, lane.bearing() + i, right, n, settings, limit);
            if (!Double.isNaN(v) && v < 0) {
                edgeSum += v;
                edgeHits++;
            }
        }
        double centreSum = 0;
        int centreHits = 0;
        n = nearbyStrips(x, y, lane, limit, MarkingKind.CENTRE);
        for (double i = 0; i >= -settings.rightArc() - 1e-9; i -= settings.angularStep()) {
            double v = lateralOfHit(x, y, lane.bearing() + i, right, n, settings, limit);
            if (!Double.isNaN(v) && v > 0) {
                centreSum += v;
                centreHits++;
            }
        }
        if (edgeHits == 0 && centreHits == 0) {
            return LaneEstimate.NOTHING_SEEN;
        }
        return new LaneEstimate(edgeHits > 0, edgeHits > 0 ? edgeSum / edgeHits : 0,
                centreHits > 0, centreHits > 0 ? centreSum / centreHits : 0);
    }

    /** The lateral offset (right positive) of the ray's first marking hit, or NaN. */
    private double lateralOfHit(double x, double y, double bearing, Compass right, int nStrips,
                                CameraSettings settings, double limit) {
        double r = Math.toRadians(bearing);
        double dx = Math.sin(r);
        double dy = Math.cos(r);
        double reach = Math.min(limit, roadReach.along(x, y, dx, dy));
        double best = Double.NaN;
        for (int s = 0; s < nStrips; s++) {
            if (strips[s].rayInterval(x, y, dx, dy, interval)) {
                double d = Rays.firstSample(interval[0], interval[1], settings.rangeStart(), settings.rangeStep(), reach);
                if (!Double.isNaN(d) && (Double.isNaN(best) || d < best)) {
                    best = d;
                }
            }
        }
        if (Double.isNaN(best)) {
            return Double.NaN;
        }
        return best * (dx * right.dx() + dy * right.dy());
    }

    /** How far along the ray the road surface reaches without a gap, from the car. */


    private int nearbyStrips(double x, double y, Compass lane, double limit, MarkingKind kind) {
        int n = 0;
        boolean northSouth = lane.isNorthSouth();
        for (Marking marking : network.markings()) {
            Rect strip = marking.strip();
            // the camera follows lines that run along the lane; across-lines belong to other roads
            boolean alongLane = northSouth ? strip.height() > strip.width() : strip.width() > strip.height();
            if (marking.kind() == kind && alongLane && n < MAX_CANDIDATES && near(strip, x, y, limit)) {
                strips[n++] = strip;
            }
        }
        return n;
    }

    private static boolean near(Rect r, double x, double y, double limit) {
        return r.minX() <= x + limit && r.maxX() >= x - limit && r.minY() <= y + limit && r.maxY() >= y - limit;
    }
}
