package sitcov.judge;

import java.util.ArrayList;
import java.util.List;
import sitcov.oracle.Accident;
import sitcov.oracle.AccidentDetector;
import sitcov.oracle.NewAccidents;
import sitcov.oracle.RunResult;

/**
 * Watches a faulty run's accidents as they happen for the first one the fault-free run lacks,
 * matching them in order exactly as {@link NewAccidents#between} does: an event unmatched when
 * it happens stays unmatched whatever follows, so the verdict is settled from that tick on.
 */
final class VerdictWatch {
    private final List<Accident> unmatched;
    /** Where the reference's controller failed, its run ended: nothing after can be compared. */
    private final long horizon;
    private int seen;

    VerdictWatch(RunResult faultFree) {
        this.unmatched = new ArrayList<>(faultFree.accidents());
        this.horizon = faultFree.controllerFailure().isPresent() ? faultFree.ticks() : Long.MAX_VALUE;
    }

    /**
     * Whether the run's accidents up to {@code tick} include one the fault-free run lacks, or the run
     * reached the tick where the reference's controller failed.
     */
    boolean settled(AccidentDetector detector, long tick) {
        if (tick + 1 >= horizon) {
            return true;
        }
        if (seen == detector.accidentCount()) {
            return false;
        }
        List<Accident> soFar = detector.accidents();
        while (seen < soFar.size()) {
            Accident match = NewAccidents.firstSame(unmatched, soFar.get(seen++));
            if (match == null) {
                return true;
            }
            unmatched.remove(match);
        }
        return false;
    }
}
