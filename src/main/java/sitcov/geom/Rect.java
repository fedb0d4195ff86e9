package sitcov.geom;

/** An axis-aligned rectangle; containment includes the edges. */
public record Rect(double minX, double minY, double maxX, double maxY) {
    public Rect {
        if (!(minX <= maxX && minY <= maxY)) {
            throw new IllegalArgumentException("a rectangle needs min <= max: " + minX + "," + minY + " " + maxX + "," + maxY);
        }
    }

    /** The square of side {@code size} centred on ({@code cx}, {@code cy}). */
    public static Rect square(double cx, double cy, double size) {
        double h = size / 2;
        return new Rect(cx - h, cy - h, cx + h, cy + h);
    }

    public static Rect spanning(double x1, double y1, double x2, double y2) {
        return new Rect(Math.min(x1, x2), Math.min(y1, y2), Math.max(x1, x2), Math.max(y1, y2));
    }

    public double width() {
        return maxX - minX;
    }

    public double height() {
        return maxY - minY;
    }

    public Vec2 centre() {
        return new Vec2((minX + maxX) / 2, (minY + maxY) / 2);
    }

    public boolean contains(double x, double y) {
        return x >= minX && x <= maxX && y >= minY && y <= maxY;
    }

    public boolean contains(Vec2 p) {
        return contains(p.x(), p.y());
    }

    public boolean contains(Rect other) {
        return other.minX >= minX && other.maxX <= maxX && other.minY >= minY && other.maxY <= maxY;
    }

    /** True when the interiors overlap: rectangles that only touch along an edge do not. */
    public boolean overlaps(Rect other) {
        return minX < other.maxX && other.minX < maxX && minY < other.maxY && other.minY < maxY;
    }

    /** True when the closed rectangles share any point, touching included. */
    public boolean touches(Rect other) {
        return minX <= other.maxX && other.minX <= maxX && minY <= other.maxY && other.minY <= maxY;
    }

    /**
     * Where the ray from ({@code ox}, {@code oy}) along the unit vector ({@code dx}, {@code dy})
     * is inside the rectangle: entry and exit distances in {@code out}; false when it misses.
     */
    public boolean rayInterval(double ox, double oy, double dx, double dy, double[] out) {
        double hx = (maxX - minX) / 2;
        double hy = (maxY - minY) / 2;
        return Rays.slabs(ox - (minX + hx), dx, hx, oy - (minY + hy), dy, hy, out);
    }

    public Rect expanded(double margin) {
        return new Rect(minX - margin, minY - margin, maxX + margin, maxY + margin);
    }
}
