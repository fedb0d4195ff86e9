package sitcov.faults;

import java.util.Set;
import sitcov.control.Controller;
import sitcov.control.ControllerFactory;
import sitcov.control.RunStart;

/**
 * Makes the controller of one run for a controller whose variants are seeded faults of this
 * catalogue: the run's owner hands it the run's switchboard, on which it acts on the faults
 * switched on and records what each did. Any other controller is started without one.
 */
public interface SeededControllerFactory extends ControllerFactory {
    /** The controller of {@code run}, acting on the faults {@code faults} switches on and recording into it. */
    Controller start(RunStart run, FaultSwitchboard faults);

    /** Started by someone that knows no faults: every fault off, and what is recorded is read by nobody. */
    @Override
    default Controller start(RunStart run) {
        return start(run, FaultSwitchboard.none());
    }

    /**
     * This controller with {@code planted} always on, whatever a run switches on: a version of it with
     * bugs, for comparing versions. What every fault does is recorded on the run's board.
     */
    default PlantedFaults withPlanted(Set<Fault> planted) {
        return new PlantedFaults(this, planted);
    }

    /** The same controllers, each run run whole, still handed the run's faults. */
    @Override
    default SeededControllerFactory unforked() {
        SeededControllerFactory forked = this;
        return forked::start;
    }
}
