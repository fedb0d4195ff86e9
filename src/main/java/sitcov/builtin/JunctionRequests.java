package sitcov.builtin;

import sitcov.control.Command;
import sitcov.control.RightOfWay;

/**
 * The builtin car's side of the junctions' right-of-way within one tick: what the signals showed,
 * plus what it asked for and let go of since (which goes out in its command). Asking is granted
 * exactly when the signal said it would be: the world does not change while the car decides.
 */
final class JunctionRequests {
    private RightOfWay signals;
    private Command out;

    void startTick(RightOfWay signals, Command out) {
        this.signals = signals;
        this.out = out;
    }

    /** Asks for {@code junction}: true (and asked in the command) when the signal showed it would be granted. */
    boolean request(int junction) {
        // a junction the car let go of this tick was its own: the signal's answer for it still stands
        if (!signals.wouldGrant(junction)) {
            return false;
        }
        out.claim(junction);
        return true;
    }

    void release(int junction) {
        if (junction >= 0) {
            out.release(junction);
        }
    }

    /** Whether the car holds {@code junction} now: asked for this tick, or held and not let go of since. */
    boolean isHeld(int junction) {
        for (int i = 0; i < out.claimCount(); i++) {
            if (out.claimAt(i) == junction) {
                return true;
            }
        }
        if (!signals.holds(junction)) {
            return false;
        }
        for (int i = 0; i < out.releaseCount(); i++) {
            if (out.releaseAt(i) == junction) {
                return false;
            }
        }
        return true;
    }
}
