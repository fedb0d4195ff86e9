package sitcov.faults;

import java.util.Set;
import sitcov.control.Controller;
import sitcov.control.RunStart;

/**
 * A version of a seeded controller with faults planted in it: its runs act on {@code planted} as
 * well as on the run's own faults, and both are recorded on the run's board. A run of it is a faulty
 * run of {@code reference}, so it can be forked from the reference's run where its faults depart.
 */
public record PlantedFaults(SeededControllerFactory reference, Set<Fault> planted) implements SeededControllerFactory {
    public PlantedFaults {
        planted = Set.copyOf(planted);
    }

    @Override
    public Controller start(RunStart run, FaultSwitchboard faults) {
        return reference.start(run, faults.alsoWith(planted));
    }
}
