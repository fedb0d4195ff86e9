package sitcov.experiment;

import sitcov.coverage.Bins;
import sitcov.world.Layout;

/**
 * A candidate map drawn from a replication's stream: its position in the stream, its layout (no
 * moving cars yet: that is all coverage needs), its criteria values and its cell.
 */
public record Candidate(int index, Layout layout, double[] criteria, int cell) {
    public Candidate {
        criteria = criteria.clone();
    }

    @Override
    public double[] criteria() {
        return criteria.clone();
    }

    public long externalSeed() {
        return layout.seed();
    }

    /** Has a Target and a car start, so the car can be run on it. */
    public boolean runnable() {
        return layout.isRunnable();
    }

    /** Falls in a cell of the grid (not in the invalid bin). */
    public boolean inGrid() {
        return cell != Bins.INVALID;
    }
}
