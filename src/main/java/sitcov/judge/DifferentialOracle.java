package sitcov.judge;

import java.util.List;
import java.util.Optional;
import sitcov.faults.Activation;
import sitcov.faults.Fault;
import sitcov.oracle.Accident;
import sitcov.oracle.Failure;
import sitcov.oracle.NewAccidents;
import sitcov.oracle.RunResult;

/**
 * A variant counts as found on a map only when it fails where the reference run of the same map and
 * internal seed does not: an accident the reference does not have, or a controller failure (no
 * command in time, an exit, garbage) where the reference's controller did not fail. Failures the
 * reference has anyway are not the variant's. Where the reference's controller failed, its run
 * stopped there, so only what the variant did before that tick can be compared.
 */
public final class DifferentialOracle {
    private DifferentialOracle() {
    }

    /** Judges seeded {@code fault} from a faulty run and the fault-free run of the same seeds. */
    public static FaultVerdict judge(RunResult faultFree, RunRecord faulty, Fault fault) {
        Activation activation = faulty.activations().get(fault.ordinal());
        return judge(faultFree, faulty.result(), new Variant.Seeded(fault), activation.reached(),
                activation.effectiveCount(), activation.firstEffectiveTick());
    }

    /**
     * Judges {@code variant} from its run and the reference run of the same seeds: it was reached
     * ({@code reached}) and acted on {@code effectiveCount} ticks, first at {@code firstEffectiveTick}.
     */
    public static FaultVerdict judge(RunResult reference, RunResult run, Variant variant, boolean reached,
                                      long effectiveCount, long firstEffectiveTick) {
        if (reference.externalSeed() != run.externalSeed() || reference.internalSeed() != run.internalSeed()) {
            throw new IllegalArgumentException("the differential oracle compares runs of the same seeds, got "
                    + reference.externalSeed() + "/" + reference.internalSeed() + " and "
                    + run.externalSeed() + "/" + run.internalSeed());
        }
        List<Accident> fresh = fresh(reference, run);
        Optional<Failure> controller = run.controllerFailure()
                .filter(f -> !reference.controllerFailure().equals(Optional.of(f)));
        Optional<Accident> first = fresh.stream().findFirst();
        Optional<Failure> failure = first.map(a -> Failure.of(a.type())).or(() -> controller);
        Detection detection;
        if (failure.isPresent()) {
            detection = Detection.FOUND;
        } else if (effectiveCount > 0) {
            detection = Detection.EFFECT_NO_FAILURE;
        } else if (reached) {
            detection = Detection.REACHED_NO_EFFECT;
        } else {
            detection = Detection.NOT_REACHED;
        }
        return new FaultVerdict(variant, run.externalSeed(), run.internalSeed(), detection, first, failure,
                reached && run.failed(), reached, effectiveCount, firstEffectiveTick, run);
    }

    /** The run's accidents the reference lacks, up to where the reference's controller failed if it did. */
    private static List<Accident> fresh(RunResult reference, RunResult run) {
        List<Accident> fresh = NewAccidents.between(reference, run);
        if (reference.controllerFailure().isEmpty()) {
            return fresh;
        }
        return fresh.stream().filter(a -> a.tick() < reference.ticks()).toList();
    }
}
