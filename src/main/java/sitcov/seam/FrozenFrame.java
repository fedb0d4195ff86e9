package sitcov.seam;

import java.util.random.RandomGenerator;

/**
 * From time to time the observation freezes: each tick, unless one is under way, a freeze starts with
 * the fault's chance (drawn from its stream), and the frame of the tick it starts is handed to the
 * controller again for the following ticks, the whole freeze lasting the fault's number of ticks.
 */
final class FrozenFrame extends FrameView {
    private RandomGenerator draws;
    private double chance;
    private int ticks;
    private Frame frozen = new Frame();
    /** Ticks of the freeze still to come after this one; 0 when none is under way. */
    private int left;
    private boolean startsNow;
    private boolean stale;

    FrozenFrame(RandomGenerator draws, double chance, int ticks) {
        this.draws = draws;
        this.chance = chance;
        this.ticks = ticks;
    }

    @Override
    void started() {
        stale = left > 0;
        if (stale) {
            left--;
            startsNow = false;
        } else {
            startsNow = draws.nextDouble() < chance;
        }
    }

    @Override
    Frame shown() {
        return stale ? frozen : null;
    }

    @Override
    void endTick(Consults consulted) {
        if (startsNow) {
            frozen.remember(real, consulted.ever());
            left = ticks - 1;
        }
    }
}
