package sitcov.judge;

import java.util.Optional;
import sitcov.faults.Activation;
import sitcov.faults.Fault;
import sitcov.oracle.Accident;
import sitcov.oracle.RunResult;

/**
 * The verdict on one fault for one map and internal seed: the differential oracle's
 * {@link Detection} (with the first accident the fault-free run lacks, when FOUND) and, beside it,
 * the paper's weaker notion: the fault was triggered (reached) and the faulty run had any accident
 * at all (§5.2); and the faulty run itself.
 */
public record FaultVerdict(Fault fault, long externalSeed, long internalSeed, Detection detection,
                           Optional<Accident> newAccident, boolean foundByPaperNotion, Activation activation,
                           RunResult faultyRun) {
    @Override
    public String toString() {
        return "fault " + fault.id() + " (" + fault.label() + ") on map " + externalSeed + " internal seed "
                + internalSeed + ": " + detection + newAccident.map(a -> " by " + a.type() + " at tick " + a.tick()).orElse("")
                + (foundByPaperNotion ? "; an accident by the paper's notion" : "");
    }
}
