package sitcov.oracle;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import sitcov.geom.BoxGap;
import sitcov.geom.Rect;

/**
 * The edge of the road surface — the boundary of the union of the roads' rectangles, the surface
 * the accident oracle's LEAVEROAD asks a footprint to stay on ({@code RoadNetwork.isOnRoad}) — and a
 * footprint's signed distance to it: positive, the distance from a footprint wholly on the road to
 * the nearest edge; negative when part of it is off, minus the larger of how far its worst corner is
 * from the road and how deep the road's edge reaches into it (a corner of the surface between two
 * roads can cut into a footprint whose four corners are all on the road). Worked out once per map;
 * asking allocates nothing, and one instance serves one run at a time.
 */
final class RoadEdges {
    private double[] minX;
    private double[] minY;
    private double[] maxX;
    private double[] maxY;
    /** The boundary's pieces: from (x1, y1) to (x2, y2), each along x or y. */
    private double[] x1;
    private double[] y1;
    private double[] x2;
    private double[] y2;
    /** The road that last held a point {@link #distanceToRoad} was asked about, or −1: tried first. */
    private int lastHolding = -1;
    /** Scratch: each piece's squared distance from the footprint's centre this tick. */
    private double[] centreDistance;

    RoadEdges(List<Rect> surfaces) {
        int n = surfaces.size();
        minX = new double[n];
        minY = new double[n];
        maxX = new double[n];
        maxY = new double[n];
        for (int i = 0; i < n; i++) {
            Rect r = surfaces.get(i);
            minX[i] = r.minX();
            minY[i] = r.minY();
            maxX[i] = r.maxX();
            maxY[i] = r.maxY();
        }
        List<double[]> pieces = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            // each side: fixed coordinate, the span along it, outward sign, whether it runs along x
            addUncovered(i, minY[i], minX[i], maxX[i], -1, true, pieces);
            addUncovered(i, maxY[i], minX[i], maxX[i], 1, true, pieces);
            addUncovered(i, minX[i], minY[i], maxY[i], -1, false, pieces);
            addUncovered(i, maxX[i], minY[i], maxY[i], 1, false, pieces);
        }
        centreDistance = new double[pieces.size()];
        x1 = new double[pieces.size()];
        y1 = new double[pieces.size()];
        x2 = new double[pieces.size()];
        y2 = new double[pieces.size()];
        for (int k = 0; k < pieces.size(); k++) {
            double[] p = pieces.get(k);
            x1[k] = p[0];
            y1[k] = p[1];
            x2[k] = p[2];
            y2[k] = p[3];
        }
    }

    /** The parts of one side of rectangle {@code i} with no other rectangle just outside them. */
    private void addUncovered(int i, double fixed, double from, double to, int outward, boolean alongX,
                              List<double[]> pieces) {
        List<double[]> covered = new ArrayList<>();
        for (int q = 0; q < minX.length; q++) {
            if (q == i) {
                continue;
            }
            double lo = alongX ? minY[q] : minX[q];
            double hi = alongX ? maxY[q] : maxX[q];
            boolean reachesOut = outward > 0 ? lo <= fixed && hi > fixed : lo < fixed && hi >= fixed;
            double start = Math.max(from, alongX ? minX[q] : minY[q]);
            double end = Math.min(to, alongX ? maxX[q] : maxY[q]);
            if (reachesOut && start < end) {
                covered.add(new double[] {start, end});
            }
        }
        covered.sort(Comparator.comparingDouble(c -> c[0]));
        double at = from;
        for (double[] c : covered) {
            if (c[0] > at) {
                pieces.add(piece(fixed, at, c[0], alongX));
            }
            at = Math.max(at, c[1]);
        }
        if (at < to) {
            pieces.add(piece(fixed, at, to, alongX));
        }
    }

    private static double[] piece(double fixed, double from, double to, boolean alongX) {
        return alongX ? new double[] {from, fixed, to, fixed} : new double[] {fixed, from, fixed, to};
    }

    /** How many pieces the edge has (for tests). */
    int pieces() {
        return x1.length;
    }

    /** The signed distance from the box (centre, unit forward axis, half sizes) to the road's edge. */
    double margin(double cx, double cy, double fx, double fy, double hl, double hw) {
        double worstOff = 0;
        for (int k = 0; k < 4; k++) {
            double along = k < 2 ? hl : -hl;
            double across = k == 0 || k == 3 ? hw : -hw;
            worstOff = Math.max(worstOff, distanceToRoad(cx + along * fx + across * fy, cy + along * fy - across * fx));
        }
        // the footprint is no farther from a piece than its centre is, and no nearer than that less its
        // reach: only pieces whose centre distance, less the reach, beats the nearest centre distance count
        double reach = Math.sqrt(hl * hl + hw * hw);
        // squares first: the root of the least square is the least root (the root is rounded exactly,
        // and never falls), and a piece whose square is far beyond the cut below needs no root at all
        double leastSquare = Double.POSITIVE_INFINITY;
        for (int k = 0; k < x1.length; k++) {
            double ox = Math.max(Math.max(x1[k] - cx, cx - x2[k]), 0);
            double oy = Math.max(Math.max(y1[k] - cy, cy - y2[k]), 0);
            centreDistance[k] = ox * ox + oy * oy;
            leastSquare = Math.min(leastSquare, centreDistance[k]);
        }
        double bound = Math.sqrt(leastSquare);
        // beyond this square, root less reach exceeds bound by a millionth of the cut: far more than rounding
        double surelyBeyond = (bound + reach) * (1 + 1e-6);
        double surelyBeyondSquare = surelyBeyond * surelyBeyond;
        double nearest = Double.POSITIVE_INFINITY;
        double deepest = worstOff;
        for (int k = 0; k < x1.length; k++) {
            if (centreDistance[k] > surelyBeyondSquare || Math.sqrt(centreDistance[k]) - reach > bound) {
                continue;
            }
            double d = BoxGap.segmentSignedDistance(x1[k], y1[k], x2[k], y2[k], cx, cy, fx, fy, hl, hw);
            if (d < 0) {
                deepest = Math.max(deepest, -d);
            } else {
                nearest = Math.min(nearest, d);
            }
        }
        return deepest > 0 ? -deepest : nearest;
    }

    /** The distance from a point to the nearest road rectangle: 0 on the road. */
    private double distanceToRoad(double x, double y) {
        // a point a road holds is 0 from the road, as the scan below would find (its squares are never
        // below 0); the road that held the last point asked about holds most points asked about next
        int last = lastHolding;
        if (last >= 0 && x >= minX[last] && x <= maxX[last] && y >= minY[last] && y <= maxY[last]) {
            return 0;
        }
        double best = Double.POSITIVE_INFINITY;
        for (int i = 0; i < minX.length; i++) {
            double dx = Math.max(Math.max(minX[i] - x, x - maxX[i]), 0);
            double dy = Math.max(Math.max(minY[i] - y, y - maxY[i]), 0);
            double square = dx * dx + dy * dy;
            if (square == 0 && best != 0) {
                lastHolding = i;
            }
            best = Math.min(best, square);
        }
        return Math.sqrt(best);
    }
}
