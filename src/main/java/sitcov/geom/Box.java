package sitcov.geom;

import java.util.List;

/**
 * An oriented rectangle: a vehicle footprint. Its long side ({@code length}) lies along the
 * bearing. Vehicles are anchored at their front centre ({@link #behind}), parked cars at their
 * centre ({@link #centred}). Immutable; its trigonometry is computed once.
 */
public final class Box {
    private static final double EPS = 1e-9;

    private final double cx;
    private final double cy;
    private final double bearing;
    private final double halfLength;
    private final double halfWidth;
    // unit forward (fx, fy) and unit side (sx, sy) axes
    private final double fx;
    private final double fy;
    private final double sx;
    private final double sy;

    private Box(double cx, double cy, double bearing, double length, double width) {
        this(cx, cy, bearing, Bearing.dx(bearing), Bearing.dy(bearing), length, width);
    }

    private Box(double cx, double cy, double bearing, double fx, double fy, double length, double width) {
        if (!(length > 0 && width > 0)) {
            throw new IllegalArgumentException("a box needs a positive length and width");
        }
        this.cx = cx;
        this.cy = cy;
        this.bearing = bearing;
        this.halfLength = length / 2;
        this.halfWidth = width / 2;
        this.fx = fx;
        this.fy = fy;
        this.sx = fy;
        this.sy = -fx;
    }

    /** A footprint whose front centre is at ({@code x}, {@code y}) and whose body trails behind it. */
    public static Box behind(double x, double y, double bearing, double length, double width) {
        double h = length / 2;
        return new Box(x - h * Bearing.dx(bearing), y - h * Bearing.dy(bearing), bearing, length, width);
    }

    /**
     * {@link #behind(double, double, double, double, double)} for a caller that keeps its
     * heading's unit vector: ({@code fx}, {@code fy}) must be ({@code Bearing.dx(bearing)},
     * {@code Bearing.dy(bearing)}), which saves working them out again.
     */
    public static Box behind(double x, double y, double bearing, double fx, double fy, double length, double width) {
        double h = length / 2;
        return new Box(x - h * fx, y - h * fy, bearing, fx, fy, length, width);
    }

    /** A footprint centred on ({@code x}, {@code y}). */
    public static Box centred(double x, double y, double bearing, double length, double width) {
        return new Box(x, y, bearing, length, width);
    }

    public Vec2 centre() {
        return new Vec2(cx, cy);
    }

    /** The centre's x, without making a point (hot loops read it). */
    public double centreX() {
        return cx;
    }

    public double centreY() {
        return cy;
    }

    public double bearing() {
        return bearing;
    }

    public double length() {
        return 2 * halfLength;
    }

    public double width() {
        return 2 * halfWidth;
    }

    /** The four corners, front-left first, going round: x0, y0, x1, y1, ... */
    public double[] corners() {
        double ax = fx * halfLength;
        double ay = fy * halfLength;
        double bx = sx * halfWidth;
        double by = sy * halfWidth;
        return new double[] {
            cx + ax + bx, cy + ay + by,
            cx + ax - bx, cy + ay - by,
            cx - ax - bx, cy - ay - by,
            cx - ax + bx, cy - ay + by,
        };
    }

    /** The smallest axis-aligned rectangle holding the box. */
    public Rect bounds() {
        double ex = Math.abs(fx) * halfLength + Math.abs(sx) * halfWidth;
        double ey = Math.abs(fy) * halfLength + Math.abs(sy) * halfWidth;
        return new Rect(cx - ex, cy - ey, cx + ex, cy + ey);
    }

    /** Whether the point lies in the box, edges included. */
    public boolean contains(double x, double y) {
        double dx = x - cx;
        double dy = y - cy;
        return Math.abs(dx * fx + dy * fy) <= halfLength + EPS && Math.abs(dx * sx + dy * sy) <= halfWidth + EPS;
    }

    /** Whether the interiors overlap (separating-axis test); boxes that only touch do not. */
    public boolean overlaps(Box o) {
        double dx = o.cx - cx;
        double dy = o.cy - cy;
        return !separatedAlong(fx, fy, halfLength, dx, dy, o)
                && !separatedAlong(sx, sy, halfWidth, dx, dy, o)
                && !o.separatedAlong(o.fx, o.fy, o.halfLength, -dx, -dy, this)
                && !o.separatedAlong(o.sx, o.sy, o.halfWidth, -dx, -dy, this);
    }

    /** Whether the interiors of this box and the rectangle overlap. */
    public boolean overlaps(Rect r) {
        double rhx = r.width() / 2;
        double rhy = r.height() / 2;
        double dx = (r.minX() + r.maxX()) / 2 - cx;
        double dy = (r.minY() + r.maxY()) / 2 - cy;
        // axes of the rectangle: x and y
        double ex = Math.abs(fx) * halfLength + Math.abs(sx) * halfWidth;
        double ey = Math.abs(fy) * halfLength + Math.abs(sy) * halfWidth;
        if (Math.abs(dx) >= ex + rhx - EPS || Math.abs(dy) >= ey + rhy - EPS) {
            return false;
        }
        // axes of the box
        double rf = rhx * Math.abs(fx) + rhy * Math.abs(fy);
        double rs = rhx * Math.abs(sx) + rhy * Math.abs(sy);
        return Math.abs(dx * fx + dy * fy) < halfLength + rf - EPS && Math.abs(dx * sx + dy * sy) < halfWidth + rs - EPS;
    }

    /**
     * Where the ray from ({@code ox}, {@code oy}) along the unit vector ({@code dx}, {@code dy})
     * is inside the box: writes the entry and exit distances to {@code out[0]} and {@code out[1]}
     * and returns true, or returns false when the ray misses. Allocates nothing.
     */
    public boolean rayInterval(double ox, double oy, double dx, double dy, double[] out) {
        double rx = ox - cx;
        double ry = oy - cy;
        return Rays.slabs(rx * fx + ry * fy, dx * fx + dy * fy, halfLength,
                rx * sx + ry * sy, dx * sx + dy * sy, halfWidth, out);
    }

    /** Whether every point of the box lies in the union of {@code rects} (which must have no holes). */
    public boolean isCoveredBy(List<Rect> rects) {
        double[] c = corners();
        for (int i = 0; i < 4; i++) {
            int j = (i + 1) % 4;
            if (!Segments.isCovered(c[2 * i], c[2 * i + 1], c[2 * j], c[2 * j + 1], rects)) {
                return false;
            }
        }
        return true;
    }

    private boolean separatedAlong(double ax, double ay, double half, double dx, double dy, Box o) {
        double projected = Math.abs(o.fx * ax + o.fy * ay) * o.halfLength + Math.abs(o.sx * ax + o.sy * ay) * o.halfWidth;
        return Math.abs(dx * ax + dy * ay) >= half + projected - EPS;
    }

    @Override
    public String toString() {
        return "Box[centre=(" + cx + ", " + cy + "), bearing=" + bearing + ", " + length() + "x" + width() + "]";
    }
}
