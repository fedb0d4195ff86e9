package sitcov.judge;

import java.util.Optional;
import sitcov.faults.Fault;
import sitcov.oracle.AccidentType;

/**
 * What an experiment keeps of one fault on one map: the faulty run, what the fault did, the
 * differential oracle's detection (with the type of the first new accident) and the paper's notion.
 */
public record FaultOutcome(Fault fault, RunSummary run, boolean reached, boolean effective, long firstEffectiveTick,
                           Detection detection, Optional<AccidentType> newAccident, boolean paperFound) {
    public static FaultOutcome of(FaultVerdict v) {
        return new FaultOutcome(v.fault(), RunSummary.of(v.faultyRun()), v.activation().reached(),
                v.activation().effective(), v.activation().firstEffectiveTick(), v.detection(),
                v.newAccident().map(a -> a.type()), v.foundByPaperNotion());
    }

    /**
     * Found under the differential oracle, or under the paper's notion: the fault was triggered
     * (reached) and the run had an accident (§5.2). Folders written before the notion required
     * {@code reached} hold any accident in {@code paperFound}; requiring it here reads them alike.
     */
    public boolean found(Notion notion) {
        return notion == Notion.PAPER ? reached && paperFound : detection.found();
    }
}
