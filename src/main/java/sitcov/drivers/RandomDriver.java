package sitcov.drivers;

import sitcov.experiment.Candidate;
import sitcov.experiment.Driver;
import sitcov.experiment.DriverSession;

/** The paper's random driver: every runnable candidate is run, in the order drawn. */
final class RandomDriver implements Driver {
    @Override
    public void drive(DriverSession session) {
        while (session.budgetLeft()) {
            Candidate c = session.nextCandidate();
            if (c.runnable()) {
                session.run(c);
            }
        }
    }
}
