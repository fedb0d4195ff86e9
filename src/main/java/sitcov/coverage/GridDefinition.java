package sitcov.coverage;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import sitcov.world.Layout;

/**
 * Which criteria span the coverage grid and how each is binned, read from a small text file:
 * <pre>
 * sitcov-grid 1
 * criterion target-obstacle 1.01 6.01 11.01 16.01 21.01 26.01 inf
 * </pre>
 * one line per criterion with its bin edges ({@code inf} for an open top); {@code #} starts a comment.
 */
public record GridDefinition(List<Criterion> criteria, List<Bins> bins) {
    public static final String HEADER = "sitcov-grid 1";
    /** Every cell has a counter; a grid this large no experiment could fill anyway. */
    public static final int MAX_CELLS = 1_000_000;

    public GridDefinition {
        criteria = List.copyOf(criteria);
        bins = List.copyOf(bins);
        if (criteria.isEmpty() || criteria.size() != bins.size()) {
            throw new IllegalArgumentException("a grid needs at least one criterion, each with its bins");
        }
        long cells = 1;
        for (Bins b : bins) {
            cells *= b.count();
            if (cells > MAX_CELLS) {
                throw new IllegalArgumentException("a grid of more than " + MAX_CELLS + " cells is too large to count"
                        + " (its bins multiply past that); use fewer bins or criteria");
            }
        }
    }

    /**
     * The paper's 6×6×6 grid (experiments/README.md, "Situation coverage"; the same as experiments/paper-grid.txt),
     * with a
     * value outside every bin counted as invalid.
     */
    public static GridDefinition paper() {
        double inf = Double.POSITIVE_INFINITY;
        return new GridDefinition(List.of(Criterion.TARGET_TO_OBSTACLE, Criterion.START_TO_TARGET,
                Criterion.PREVIOUS_JUNCTION_TO_TARGET), List.of(
                new Bins(new double[] {1.01, 6.01, 11.01, 16.01, 21.01, 26.01, inf}),
                new Bins(new double[] {0, 40, 80, 120, 160, 200, 240}),
                new Bins(new double[] {0, 10, 20, 30, 40, 50, inf})));
    }

    public int cells() {
        int cells = 1;
        for (Bins b : bins) {
            cells *= b.count();
        }
        return cells;
    }

    /** The criteria values of a layout, in the grid's criterion order. */
    public double[] values(Layout layout) {
        double[] v = new double[criteria.size()];
        for (int i = 0; i < v.length; i++) {
            v[i] = criteria.get(i).value(layout);
        }
        return v;
    }

    /** The cell of these criteria values: 0 .. cells()-1, the first criterion varying slowest; or {@link Bins#INVALID}. */
    public int cellOf(double[] values) {
        int cell = 0;
        for (int i = 0; i < values.length; i++) {
            int bin = bins.get(i).of(values[i]);
            if (bin == Bins.INVALID) {
                return Bins.INVALID;
            }
            cell = cell * bins.get(i).count() + bin;
        }
        return cell;
    }

    /** The bin of criterion {@code criterion} in {@code cell}. */
    public int binOf(int cell, int criterion) {
        int rest = cell;
        for (int i = bins.size() - 1; i > criterion; i--) {
            rest /= bins.get(i).count();
        }
        return rest % bins.get(criterion).count();
    }

    /**
     * The cell of these bins, one per criterion in the grid's order: cells number their bins mixed-radix,
     * the first criterion varying slowest, as {@link #cellOf(double[])} does.
     */
    public int cellAt(int... binOfEach) {
        if (binOfEach.length != bins.size()) {
            throw new IllegalArgumentException("a cell of this grid has " + bins.size() + " bins, got " + binOfEach.length);
        }
        int cell = 0;
        for (int i = 0; i < binOfEach.length; i++) {
            int count = bins.get(i).count();
            if (binOfEach[i] < 0 || binOfEach[i] >= count) {
                throw new IllegalArgumentException("criterion " + criteria.get(i).key() + " has bins 0.." + (count - 1)
                        + ", not " + binOfEach[i]);
            }
            cell = cell * count + binOfEach[i];
        }
        return cell;
    }

    /**
     * The cells next to {@code cell}: one bin down or up in one criterion, the rest alike. Listed the last
     * criterion first, each the bin below before the bin above; coverage search draws from this order, so
     * changing it changes its results.
     */
    public List<Neighbour> neighbours(int cell) {
        List<Neighbour> next = new ArrayList<>();
        int stride = 1;
        for (int c = bins.size() - 1; c >= 0; c--) {
            int count = bins.get(c).count();
            int bin = (cell / stride) % count;
            if (bin > 0) {
                next.add(new Neighbour(c, bin, -1, cell - stride));
            }
            if (bin < count - 1) {
                next.add(new Neighbour(c, bin, 1, cell + stride));
            }
            stride *= count;
        }
        return next;
    }

    /**
     * A cell next to another: criterion {@code criterion} is in bin {@code bin + step} in {@code cell}
     * and in bin {@code bin} in the other; {@code step} is −1 or +1.
     */
    public record Neighbour(int criterion, int bin, int step, int cell) {
    }

    /** The definition as a grid file: reading it back gives the same grid, and equal grids give equal text. */
    public String format() {
        StringBuilder out = new StringBuilder(HEADER).append('\n');
        for (int i = 0; i < criteria.size(); i++) {
            out.append("criterion ").append(criteria.get(i).key());
            for (double e : bins.get(i).edges()) {
                out.append(' ').append(e == Double.POSITIVE_INFINITY ? "inf" : Double.toString(e));
            }
            out.append('\n');
        }
        return out.toString();
    }

    public static GridDefinition read(Path file) throws IOException {
        try {
            return parse(Files.readAllLines(file), file.toString());
        } catch (java.nio.charset.CharacterCodingException e) {
            throw new IllegalArgumentException(file + ": not UTF-8 text (is this a grid file?)");
        }
    }

    /** A bin edge in metres, or {@code inf} for an open top; anything else is named with the fix. */
    private static double edge(String text, String criterion) {
        if (text.equalsIgnoreCase("inf")) {
            return Double.POSITIVE_INFINITY;
        }
        try {
            double v = Double.parseDouble(text);
            if (Double.isFinite(v) && text.matches("[-+0-9.eE]+")) {
                return v;
            }
        } catch (NumberFormatException e) {
            // reported below
        }
        throw new IllegalArgumentException("criterion " + criterion + ": the edge '" + text + "' is not a number; edges"
                + " are metres written as numbers such as 0 40 80.5, or inf for an open top");
    }

    /** @throws IllegalArgumentException naming the line and what was expected */
    public static GridDefinition parse(List<String> lines, String source) {
        List<Criterion> criteria = new ArrayList<>();
        List<Bins> bins = new ArrayList<>();
        boolean header = false;
        for (int n = 0; n < lines.size(); n++) {
            String line = lines.get(n).replaceAll("#.*", "").strip();
            if (line.isEmpty()) {
                continue;
            }
            String where = source + ":" + (n + 1) + ": ";
            if (!header) {
                if (!line.equals(HEADER)) {
                    throw new IllegalArgumentException(where + "expected the first line '" + HEADER + "', found '" + line + "'");
                }
                header = true;
                continue;
            }
            String[] f = line.split("\\s+");
            if (!f[0].equals("criterion") || f.length < 4) {
                throw new IllegalArgumentException(where + "expected 'criterion NAME EDGE EDGE ...' with at least two"
                        + " edges, found '" + line + "'");
            }
            try {
                Criterion c = Criterion.ofKey(f[1]);
                if (criteria.contains(c)) {
                    throw new IllegalArgumentException("criterion " + f[1] + " is given twice");
                }
                double[] edges = new double[f.length - 2];
                for (int i = 2; i < f.length; i++) {
                    edges[i - 2] = edge(f[i], f[1]);
                }
                criteria.add(c);
                bins.add(new Bins(edges));
            } catch (IllegalArgumentException e) {
                throw new IllegalArgumentException(where + e.getMessage(), e);
            }
        }
        if (criteria.isEmpty()) {
            throw new IllegalArgumentException(source + ": no criterion lines; expected '" + HEADER
                    + "' then lines 'criterion NAME EDGE EDGE ...'");
        }
        return new GridDefinition(criteria, bins);
    }
}
