package sitcov.judge;

import java.util.List;
import java.util.Set;
import sitcov.faults.Activation;
import sitcov.faults.Fault;
import sitcov.oracle.RunResult;
import sitcov.vehicles.CommandLog;

/**
 * One simulated run: the oracle's result, the faults that were on, what each fault did, and the
 * commands the world carried out (the run's recording).
 */
public record RunRecord(RunResult result, Set<Fault> faults, List<Activation> activations, CommandLog commands) {
    public RunRecord {
        faults = Set.copyOf(faults);
        activations = List.copyOf(activations);
    }
}
