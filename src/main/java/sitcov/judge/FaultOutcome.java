package sitcov.judge;

import java.util.Optional;
import sitcov.oracle.Failure;

/**
 * What an experiment keeps of one variant on one map: the variant's run, what it did, the
 * differential oracle's detection (with the first new failure: an accident's type or the
 * controller's failure) and the paper's notion.
 */
public record FaultOutcome(Variant variant, RunSummary run, boolean reached, boolean effective, long firstEffectiveTick,
                           Detection detection, Optional<Failure> newAccident, boolean paperFound) {
    public static FaultOutcome of(FaultVerdict v) {
        return new FaultOutcome(v.variant(), RunSummary.of(v.faultyRun()), v.reached(), v.effective(),
                v.firstEffectiveTick(), v.detection(), v.newFailure(), v.foundByPaperNotion());
    }

    /** Whether {@code replayed}, judged again, is this outcome as recorded ({@link RunSummary#agrees}). */
    public boolean agrees(FaultOutcome replayed) {
        return run.agrees(replayed.run) && equals(new FaultOutcome(replayed.variant, run, replayed.reached,
                replayed.effective, replayed.firstEffectiveTick, replayed.detection, replayed.newAccident,
                replayed.paperFound));
    }

    /**
     * Found under the differential oracle, or under the paper's notion: the variant was triggered
     * (reached) and the run failed (§5.2). Folders written before the notion required
     * {@code reached} hold any accident in {@code paperFound}; requiring it here reads them alike.
     */
    public boolean found(Notion notion) {
        return notion == Notion.PAPER ? reached && paperFound : detection.found();
    }
}
