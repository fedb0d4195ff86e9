package sitcov.judge;

import java.util.List;
import sitcov.faults.Activation;
import sitcov.faults.Fault;
import sitcov.oracle.Accident;
import sitcov.oracle.NewAccidents;
import sitcov.oracle.RunResult;

/**
 * A fault counts as found on a map only when it causes an accident that the fault-free run of the
 * same map and internal seed does not have; accidents the car has anyway are not the fault's.
 */
public final class DifferentialOracle {
    private DifferentialOracle() {
    }

    /** Judges {@code fault} from a faulty run and the fault-free run of the same seeds. */
    public static FaultVerdict judge(RunResult faultFree, RunRecord faulty, Fault fault) {
        RunResult run = faulty.result();
        if (faultFree.externalSeed() != run.externalSeed() || faultFree.internalSeed() != run.internalSeed()) {
            throw new IllegalArgumentException("the differential oracle compares runs of the same seeds, got "
                    + faultFree.externalSeed() + "/" + faultFree.internalSeed() + " and "
                    + run.externalSeed() + "/" + run.internalSeed());
        }
        Activation activation = faulty.activations().get(fault.ordinal());
        List<Accident> fresh = NewAccidents.between(faultFree, run);
        Detection detection;
        if (!fresh.isEmpty()) {
            detection = Detection.FOUND;
        } else if (activation.effective()) {
            detection = Detection.EFFECT_NO_FAILURE;
        } else if (activation.reached()) {
            detection = Detection.REACHED_NO_EFFECT;
        } else {
            detection = Detection.NOT_REACHED;
        }
        return new FaultVerdict(fault, run.externalSeed(), run.internalSeed(), detection,
                fresh.stream().findFirst(), activation.reached() && run.hasAccident(), activation, run);
    }
}
