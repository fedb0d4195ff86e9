package sitcov.estimate;

import java.util.EnumSet;
import java.util.Set;
import sitcov.drivers.Stress;
import sitcov.oracle.Accident;
import sitcov.oracle.Failure;
import sitcov.oracle.RunResult;
import sitcov.world.DrawTrace;

/**
 * One simulated map of an estimate: where it was drawn (replication, stage, index, seed), its
 * likelihood under the generator and under the proposal that drew it, what it cost and how it ended.
 *
 * @param stage  {@code mc} (plain Monte Carlo), {@code ce-T} (cross-entropy stage T) or {@code is}
 *               (the final importance-sampling stage)
 * @param score  how near the run came to failing ({@link Stress}): {@link Stress#FAILED} when it failed
 */
public record Sample(int replication, String stage, int index, long seed, DrawTrace trace, long ticks,
                     double score, Set<Failure> failures) {
    public Sample {
        failures = failures.isEmpty() ? Set.of() : Set.copyOf(EnumSet.copyOf(failures));
    }

    /** The sample of a run of the map {@code trace} describes. */
    static Sample of(int replication, String stage, int index, long seed, DrawTrace trace, RunResult result) {
        Set<Failure> failures = EnumSet.noneOf(Failure.class);
        for (Accident a : result.accidents()) {
            failures.add(Failure.of(a.type()));
        }
        result.controllerFailure().ifPresent(failures::add);
        double score = failures.isEmpty() ? Stress.of(result.margins()) : Stress.FAILED;
        return new Sample(replication, stage, index, seed, trace, result.ticks(), score, failures);
    }

    public double weight() {
        return trace.weight();
    }

    public boolean failed(Failing requirement) {
        return requirement.in(failures);
    }
}
