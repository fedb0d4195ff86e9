package sitcov.geom;

import java.util.Arrays;
import java.util.List;

/** Tests on line segments from (x1, y1) to (x2, y2), parameterised by t in [0, 1]. */
public final class Segments {
    private static final double EPS = 1e-9;

    private Segments() {
    }

    /**
     * The part of the segment inside the closed rectangle, as {t0, t1}, or null when it misses
     * (Liang–Barsky clipping).
     */
    public static double[] clip(double x1, double y1, double x2, double y2, Rect r) {
        double t0 = 0;
        double t1 = 1;
        double dx = x2 - x1;
        double dy = y2 - y1;
        double[] p = {-dx, dx, -dy, dy};
        double[] q = {x1 - r.minX(), r.maxX() - x1, y1 - r.minY(), r.maxY() - y1};
        for (int i = 0; i < 4; i++) {
            if (p[i] == 0) {
                if (q[i] < -EPS) {
                    return null;
                }
            } else {
                double t = q[i] / p[i];
                if (p[i] < 0) {
                    t0 = Math.max(t0, t);
                } else {
                    t1 = Math.min(t1, t);
                }
            }
        }
        return t0 <= t1 + EPS ? new double[] {t0, t1} : null;
    }

    /** Whether every point of the segment lies in the union of the closed rectangles. */
    public static boolean isCovered(double x1, double y1, double x2, double y2, List<Rect> rects) {
        double[][] spans = new double[rects.size()][];
        int n = 0;
        for (Rect r : rects) {
            double[] span = clip(x1, y1, x2, y2, r);
            if (span != null) {
                spans[n++] = span;
            }
        }
        Arrays.sort(spans, 0, n, (a, b) -> Double.compare(a[0], b[0]));
        double reached = 0;
        for (int i = 0; i < n; i++) {
            if (spans[i][0] > reached + EPS) {
                return false;
            }
            reached = Math.max(reached, spans[i][1]);
        }
        return reached >= 1 - EPS;
    }

    /** Whether the segment meets the closed rectangle at all. */
    public static boolean meets(double x1, double y1, double x2, double y2, Rect r) {
        return clip(x1, y1, x2, y2, r) != null;
    }
}
