package sitcov.coverage;

import java.util.Arrays;

/**
 * Consecutive half-open bins [e0, e1), [e1, e2), … of one criterion. A value outside all of them
 * (or NaN) is {@link #INVALID}: it is counted apart, never folded into the first or last bin.
 */
public record Bins(double[] edges) {
    public static final int INVALID = -1;

    public Bins {
        if (edges.length < 2) {
            throw new IllegalArgumentException("bins need at least two edges, got " + edges.length);
        }
        for (int i = 1; i < edges.length; i++) {
            if (!(edges[i] > edges[i - 1])) {
                throw new IllegalArgumentException("bin edges must increase, but " + edges[i] + " follows " + edges[i - 1]);
            }
        }
        edges = edges.clone();
    }

    public int count() {
        return edges.length - 1;
    }

    /** The bin holding {@code value}, or {@link #INVALID}. */
    public int of(double value) {
        if (!(value >= edges[0]) || value >= edges[edges.length - 1]) {
            return INVALID;
        }
        int i = Arrays.binarySearch(edges, value);
        return i >= 0 ? i : -i - 2;
    }

    public double lower(int bin) {
        return edges[bin];
    }

    public double upper(int bin) {
        return edges[bin + 1];
    }

    @Override
    public double[] edges() {
        return edges.clone();
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof Bins b && Arrays.equals(edges, b.edges);
    }

    @Override
    public int hashCode() {
        return Arrays.hashCode(edges);
    }

    @Override
    public String toString() {
        return Arrays.toString(edges);
    }
}
