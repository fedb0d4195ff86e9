package sitcov.drivers;

import sitcov.experiment.Candidate;
import sitcov.experiment.Driver;
import sitcov.experiment.DriverSession;

/**
 * Runs the runnable candidates at even positions of the stream: random generation at half the
 * density. A baseline with no idea of coverage, and the smallest possible driver, which keeps the
 * extension point honest.
 */
final class EveryOtherDriver implements Driver {
    @Override
    public void drive(DriverSession session) {
        while (session.budgetLeft()) {
            Candidate c = session.nextCandidate();
            if (c.index() % 2 == 0 && c.runnable()) {
                session.run(c);
            }
        }
    }
}
