package sitcov.drivers;

import sitcov.experiment.Candidate;
import sitcov.experiment.Driver;
import sitcov.experiment.DriverSession;
import sitcov.stats.Richness;

/** The paper's coverage-filter driver: a candidate is run only if its coverage cell is still empty. */
final class CoverageFilterDriver implements Driver {
    private int[] seen = new int[0];
    private long inGrid;
    private long once;
    private long twice;

    @Override
    public void drive(DriverSession session) {
        while (session.budgetLeft()) {
            Candidate c = session.nextCandidate();
            if (c.runnable() && c.inGrid()) {
                count(c.cell());
                if (!session.covers(c.cell())) {
                    session.run(c);
                }
            }
        }
    }

    private void count(int cell) {
        if (cell >= seen.length) {
            seen = java.util.Arrays.copyOf(seen, Math.max(cell + 1, seen.length * 2));
        }
        inGrid++;
        switch (++seen[cell]) {
            case 1 -> once++;
            case 2 -> {
                once--;
                twice++;
            }
            case 3 -> twice--;
            default -> {
                // a common cell: no longer counts towards the estimate of what is unseen
            }
        }
    }

    /**
     * Most of the filter's time goes into its first candidates, which nearly all fill new cells: the
     * share of candidates drawn says little. The maps still to come are foreseen from how often the
     * cells seen so far were drawn (Chao's extrapolation), and weighed against the candidates' cost.
     */
    @Override
    public double progress(DriverSession session) {
        long left = session.candidatesLeft();
        int drawn = session.candidatesDrawn();
        if (left < 0 || drawn == 0) {
            return session.budgetSpent();
        }
        double runnable = (double) inGrid / drawn;
        double mapsToCome = Richness.expectedNew(inGrid, once, twice, Math.round(left * runnable));
        double c = session.candidateCostInMaps();
        double done = session.mapsRun() + c * drawn;
        return done / (done + mapsToCome + c * left);
    }
}
