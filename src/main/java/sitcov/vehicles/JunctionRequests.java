package sitcov.vehicles;

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
    private int[] claimed = new int[4];
    private int claimedCount;
    private int[] released = new int[4];
    private int releasedCount;

    void startTick(RightOfWay signals, Command out) {
        this.signals = signals;
        this.out = out;
        claimedCount = 0;
        releasedCount = 0;
    }

    /** Asks for {@code junction}: true (and asked in the command) when the signal showed it would be granted. */
    boolean request(int junction) {
        // a junction the car let go of this tick was its own: the signal's answer for it still stands
        if (!signals.wouldGrant(junction)) {
            return false;
        }
        out.claim(junction);
        claimed = add(claimed, claimedCount++, junction);
        return true;
    }

    void release(int junction) {
        if (junction < 0) {
            return;
        }
        out.release(junction);
        released = add(released, releasedCount++, junction);
    }

    boolean isHeld(int junction) {
        return contains(claimed, claimedCount, junction)
                || (signals.holds(junction) && !wasReleased(junction));
    }

    private boolean wasReleased(int junction) {
        return contains(released, releasedCount, junction);
    }

    private static boolean contains(int[] list, int count, int value) {
        for (int i = 0; i < count; i++) {
            if (list[i] == value) {
                return true;
            }
        }
        return false;
    }

    private static int[] add(int[] list, int at, int value) {
        int[] grown = at < list.length ? list : java.util.Arrays.copyOf(list, 2 * list.length);
        grown[at] = value;
        return grown;
    }
}
