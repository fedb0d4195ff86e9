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
    private int seen;

    VerdictWatch(RunResult faultFree) {
        this.unmatched = new ArrayList<>(faultFree.accidents());
    }

    /** Whether the run's accidents so far include one the fault-free run lacks. */
    boolean settled(AccidentDetector detector) {
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
