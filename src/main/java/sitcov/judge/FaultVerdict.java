package sitcov.judge;

import java.util.Optional;
import sitcov.faults.Activation;
import sitcov.oracle.Accident;
import sitcov.oracle.Failure;
import sitcov.oracle.RunResult;

/**
 * The verdict on one variant for one map and internal seed: the differential oracle's
 * {@link Detection} (with the first failure the reference run lacks, when FOUND: an accident, or the
 * controller's own failure) and, beside it, the paper's weaker notion: the variant was triggered
 * (reached) and its run failed at all (§5.2); what the variant did ({@code reached}, how often it
 * acted and first when); and the variant's run itself.
 */
public record FaultVerdict(Variant variant, long externalSeed, long internalSeed, Detection detection,
                           Optional<Accident> newAccident, Optional<Failure> newFailure, boolean foundByPaperNotion,
                           boolean reached, long effectiveCount, long firstEffectiveTick, RunResult faultyRun) {
    public boolean effective() {
        return effectiveCount > 0;
    }

    /** The seeded fault, when the variant is one. */
    public Optional<sitcov.faults.Fault> seededFault() {
        return variant instanceof Variant.Seeded s ? Optional.of(s.fault()) : Optional.empty();
    }

    /** What a seeded fault did, as the pictures show it; empty for another controller. */
    public Optional<Activation> activation() {
        return variant instanceof Variant.Seeded s
                ? Optional.of(new Activation(s.fault(), true, reached, effectiveCount, firstEffectiveTick))
                : Optional.empty();
    }

    @Override
    public String toString() {
        return "variant " + variant.id() + " (" + variant.label() + ") on map " + externalSeed + " internal seed "
                + internalSeed + ": " + detection + newFailure.map(f -> " by " + f + newAccident.map(a -> " at tick "
                + a.tick()).orElse("")).orElse("") + (foundByPaperNotion ? "; a failure by the paper's notion" : "");
    }
}
