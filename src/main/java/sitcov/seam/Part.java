package sitcov.seam;

import sitcov.control.Channel;

/**
 * The parts of an observation a controller can read, as bits of a mask: what it read in a tick is
 * what it received, and a seam fault is effective when one of those parts differs. The right-of-way
 * signals are read junction by junction ({@link Consults}); the tick, the road map and the Target
 * never differ.
 */
final class Part {
    static final int POSE = 1;
    static final int TRAFFIC = 1 << 1;
    static final int OBSTACLES = 1 << 2;
    static final int CAMERA = 1 << 3;
    static final int LIDAR = 1 << 4;
    static final int RIGHT_OF_WAY = 1 << 5;
    private static final int FIRST_CHANNEL = 6;
    /** Every part: a fault that changes the whole frame. */
    static final int ALL = (1 << (FIRST_CHANNEL + Channel.values().length)) - 1;

    private Part() {
    }

    static int channel(Channel c) {
        return 1 << (FIRST_CHANNEL + c.ordinal());
    }

    static boolean has(int mask, int part) {
        return (mask & part) != 0;
    }
}
