package sitcov.geom;

/**
 * How far apart two oriented boxes are, and when two moving ones would meet. Every box is given by
 * its centre ({@code cx}, {@code cy}), its unit forward axis ({@code fx}, {@code fy}) — its side axis
 * is ({@code fy}, −{@code fx}), as in {@link Box} — and its half length and half width, so that
 * callers watching a run each tick need make no {@link Box}: nothing here allocates.
 *
 * <p>The signed distance is exact both ways: apart, the Euclidean distance between the closed
 * boxes (two disjoint convex polygons are closest at a vertex of one of them, so it is the least
 * distance from a corner of either to the other); overlapping, minus the penetration depth, the
 * length of the smallest translation that separates them (for convex polygons it lies along one of
 * their edge normals, so it is the least overlap of the four separating-axis projections). Touching
 * boxes are 0 apart.
 */
public final class BoxGap {
    /** The corners' signs along the forward and side axes, in {@link Box#corners()} order. */
    private static final double[] ALONG = {1, 1, -1, -1};
    private static final double[] ACROSS = {1, -1, -1, 1};

    private BoxGap() {
    }

    /** The distance between the boxes: 0 when they touch or overlap. */
    public static double distance(Box a, Box b) {
        return Math.max(0, signedDistance(a, b));
    }

    /** The distance between the boxes apart, minus the penetration depth when they overlap. */
    public static double signedDistance(Box a, Box b) {
        double ab = a.bearing();
        double bb = b.bearing();
        return signedDistance(a.centreX(), a.centreY(), Bearing.dx(ab), Bearing.dy(ab), a.length() / 2, a.width() / 2,
                b.centreX(), b.centreY(), Bearing.dx(bb), Bearing.dy(bb), b.length() / 2, b.width() / 2);
    }

    /** {@link #signedDistance(Box, Box)} for boxes given by centre, unit forward axis and half sizes. */
    public static double signedDistance(double acx, double acy, double afx, double afy, double ahl, double ahw,
                                        double bcx, double bcy, double bfx, double bfy, double bhl, double bhw) {
        double penetration = penetration(acx, acy, afx, afy, ahl, ahw, bcx, bcy, bfx, bfy, bhl, bhw);
        if (penetration > 0) {
            return -penetration;
        }
        double best = Double.POSITIVE_INFINITY;
        for (int k = 0; k < 4; k++) {
            double ax = acx + ALONG[k] * ahl * afx + ACROSS[k] * ahw * afy;
            double ay = acy + ALONG[k] * ahl * afy - ACROSS[k] * ahw * afx;
            best = Math.min(best, pointDistance(ax, ay, bcx, bcy, bfx, bfy, bhl, bhw));
            double bx = bcx + ALONG[k] * bhl * bfx + ACROSS[k] * bhw * bfy;
            double by = bcy + ALONG[k] * bhl * bfy - ACROSS[k] * bhw * bfx;
            best = Math.min(best, pointDistance(bx, by, acx, acy, afx, afy, ahl, ahw));
        }
        return best;
    }

    /**
     * The least overlap of the boxes' projections on their four edge normals: the penetration depth
     * when positive, and 0 or less when some axis separates them (then it says nothing of the distance).
     */
    public static double penetration(double acx, double acy, double afx, double afy, double ahl, double ahw,
                                     double bcx, double bcy, double bfx, double bfy, double bhl, double bhw) {
        double dx = bcx - acx;
        double dy = bcy - acy;
        double least = overlapAlong(afx, afy, dx, dy, afx, afy, ahl, ahw, bfx, bfy, bhl, bhw);
        least = Math.min(least, overlapAlong(afy, -afx, dx, dy, afx, afy, ahl, ahw, bfx, bfy, bhl, bhw));
        least = Math.min(least, overlapAlong(bfx, bfy, dx, dy, afx, afy, ahl, ahw, bfx, bfy, bhl, bhw));
        return Math.min(least, overlapAlong(bfy, -bfx, dx, dy, afx, afy, ahl, ahw, bfx, bfy, bhl, bhw));
    }

    /** How far the boxes' shadows on the unit axis (ux, uy) overlap: negative when they are apart on it. */
    private static double overlapAlong(double ux, double uy, double dx, double dy,
                                       double afx, double afy, double ahl, double ahw,
                                       double bfx, double bfy, double bhl, double bhw) {
        return radius(ux, uy, afx, afy, ahl, ahw) + radius(ux, uy, bfx, bfy, bhl, bhw) - Math.abs(dx * ux + dy * uy);
    }

    /** Half the length of a box's shadow on the unit axis (ux, uy). */
    private static double radius(double ux, double uy, double fx, double fy, double hl, double hw) {
        return Math.abs(ux * fx + uy * fy) * hl + Math.abs(ux * fy - uy * fx) * hw;
    }

    /** The distance from a point to a closed box: 0 inside. */
    public static double pointDistance(double px, double py, double cx, double cy, double fx, double fy,
                                       double hl, double hw) {
        double dx = px - cx;
        double dy = py - cy;
        double along = Math.max(Math.abs(dx * fx + dy * fy) - hl, 0);
        double across = Math.max(Math.abs(dx * fy - dy * fx) - hw, 0);
        return Math.sqrt(along * along + across * across);
    }

    /**
     * How deep a point lies inside a box: its distance to the nearest edge, positive inside, 0 on an
     * edge, negative outside (then minus the distance to the nearest edge's line, not to the box).
     */
    public static double depth(double px, double py, double cx, double cy, double fx, double fy, double hl, double hw) {
        double dx = px - cx;
        double dy = py - cy;
        return Math.min(hl - Math.abs(dx * fx + dy * fy), hw - Math.abs(dx * fy - dy * fx));
    }

    /**
     * When two boxes moving without turning at constant velocities — box a by (avx, avy) and box b
     * by (bvx, bvy) per unit of time — first touch, from now (time 0): 0 when they touch or overlap
     * now, {@link Double#POSITIVE_INFINITY} when they never will. Exact: b moves relative to a along
     * a straight line, and the boxes meet exactly while their shadows overlap on all four edge normals,
     * so the first contact is the latest of the four times at which the shadows begin to overlap,
     * provided it comes before the earliest time at which one stops overlapping.
     */
    public static double timeToContact(double acx, double acy, double afx, double afy, double ahl, double ahw,
                                       double avx, double avy,
                                       double bcx, double bcy, double bfx, double bfy, double bhl, double bhw,
                                       double bvx, double bvy) {
        double dx = bcx - acx;
        double dy = bcy - acy;
        double wx = bvx - avx;
        double wy = bvy - avy;
        double start = 0;
        double end = Double.POSITIVE_INFINITY;
        for (int axis = 0; axis < 4; axis++) {
            double ux = axis == 0 ? afx : axis == 1 ? afy : axis == 2 ? bfx : bfy;
            double uy = axis == 0 ? afy : axis == 1 ? -afx : axis == 2 ? bfy : -bfx;
            double reach = radius(ux, uy, afx, afy, ahl, ahw) + radius(ux, uy, bfx, bfy, bhl, bhw);
            double p = dx * ux + dy * uy;
            double v = wx * ux + wy * uy;
            if (v == 0) {
                if (Math.abs(p) > reach) {
                    return Double.POSITIVE_INFINITY;
                }
                continue;
            }
            double t1 = (-reach - p) / v;
            double t2 = (reach - p) / v;
            start = Math.max(start, Math.min(t1, t2));
            end = Math.min(end, Math.max(t1, t2));
            if (start > end) {
                return Double.POSITIVE_INFINITY;
            }
        }
        return start;
    }
    /**
     * The signed distance from a segment to a box: apart or touching, the distance between them;
     * when the segment passes through the box's interior, minus how deep it reaches in (the most, over
     * the segment's points in the box, of their distance to the box's nearest edge). Exact: in the
     * box's frame that depth is the least of four linear functions along the segment, so its largest
     * value lies at an end of the segment or where two of them cross.
     */
    public static double segmentSignedDistance(double x1, double y1, double x2, double y2,
                                               double cx, double cy, double fx, double fy, double hl, double hw) {
        double u1 = (x1 - cx) * fx + (y1 - cy) * fy;
        double v1 = (x1 - cx) * fy - (y1 - cy) * fx;
        double du = (x2 - cx) * fx + (y2 - cy) * fy - u1;
        double dv = (x2 - cx) * fy - (y2 - cy) * fx - v1;
        double deepest = Math.max(depthAt(0, u1, v1, du, dv, hl, hw), depthAt(1, u1, v1, du, dv, hl, hw));
        for (int i = 0; i < 4; i++) {
            for (int j = i + 1; j < 4; j++) {
                double slopes = slope(i, du, dv) - slope(j, du, dv);
                if (slopes != 0) {
                    double t = (offset(j, u1, v1, hl, hw) - offset(i, u1, v1, hl, hw)) / slopes;
                    if (t > 0 && t < 1) {
                        deepest = Math.max(deepest, depthAt(t, u1, v1, du, dv, hl, hw));
                    }
                }
            }
        }
        if (deepest > 0) {
            return -deepest;
        }
        double best = Math.min(localPointDistance(u1, v1, hl, hw), localPointDistance(u1 + du, v1 + dv, hl, hw));
        for (int k = 0; k < 4; k++) {
            best = Math.min(best, pointSegmentDistance(ALONG[k] * hl, ACROSS[k] * hw, u1, v1, du, dv));
        }
        return best;
    }

    /** The four edge distances in the box's frame, hl − u, hl + u, hw − v, hw + v, at u + t·du, v + t·dv. */
    private static double offset(int edge, double u, double v, double hl, double hw) {
        return switch (edge) {
            case 0 -> hl - u;
            case 1 -> hl + u;
            case 2 -> hw - v;
            default -> hw + v;
        };
    }

    private static double slope(int edge, double du, double dv) {
        return switch (edge) {
            case 0 -> -du;
            case 1 -> du;
            case 2 -> -dv;
            default -> dv;
        };
    }

    private static double depthAt(double t, double u, double v, double du, double dv, double hl, double hw) {
        double pu = u + t * du;
        double pv = v + t * dv;
        return Math.min(hl - Math.abs(pu), hw - Math.abs(pv));
    }

    private static double localPointDistance(double u, double v, double hl, double hw) {
        double along = Math.max(Math.abs(u) - hl, 0);
        double across = Math.max(Math.abs(v) - hw, 0);
        return Math.sqrt(along * along + across * across);
    }

    /** The distance from (px, py) to the segment from (ax, ay) along (dx, dy). */
    public static double pointSegmentDistance(double px, double py, double ax, double ay, double dx, double dy) {
        double squared = dx * dx + dy * dy;
        double t = squared == 0 ? 0 : Math.max(0, Math.min(1, ((px - ax) * dx + (py - ay) * dy) / squared));
        double ex = ax + t * dx - px;
        double ey = ay + t * dy - py;
        return Math.sqrt(ex * ex + ey * ey);
    }
}
