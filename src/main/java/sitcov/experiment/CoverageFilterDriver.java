package sitcov.experiment;

/** The paper's coverage-filter driver: a candidate is run only if its coverage cell is still empty. */
final class CoverageFilterDriver implements Driver {
    @Override
    public void drive(DriverSession session) {
        while (session.budgetLeft()) {
            Candidate c = session.nextCandidate();
            if (c.runnable() && c.inGrid() && !session.covers(c.cell())) {
                session.run(c);
            }
        }
    }
}
