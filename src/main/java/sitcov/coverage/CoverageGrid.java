package sitcov.coverage;

/** How many maps fell in each cell of a grid, and how many in none (invalid). */
public final class CoverageGrid {
    private final GridDefinition definition;
    private final int[] counts;
    private int invalid;
    private int covered;

    public CoverageGrid(GridDefinition definition) {
        this.definition = definition;
        this.counts = new int[definition.cells()];
    }

    public GridDefinition definition() {
        return definition;
    }

    /** Counts a map in {@code cell} (or as invalid); returns whether the cell was empty before. */
    public boolean add(int cell) {
        if (cell == Bins.INVALID) {
            invalid++;
            return false;
        }
        if (counts[cell]++ == 0) {
            covered++;
            return true;
        }
        return false;
    }

    public boolean isCovered(int cell) {
        return cell != Bins.INVALID && counts[cell] > 0;
    }

    public int count(int cell) {
        return counts[cell];
    }

    public int covered() {
        return covered;
    }

    public int invalid() {
        return invalid;
    }

    public int cells() {
        return counts.length;
    }
}
