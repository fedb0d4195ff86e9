package sitcov.judge;

import java.util.List;
import java.util.Set;
import sitcov.faults.Activation;
import sitcov.faults.Fault;
import sitcov.oracle.RunResult;

/** One simulated run: the oracle's result, the faults that were on, and what each fault did. */
public record RunRecord(RunResult result, Set<Fault> faults, List<Activation> activations) {
    public RunRecord {
        faults = Set.copyOf(faults);
        activations = List.copyOf(activations);
    }
}
