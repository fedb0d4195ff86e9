package sitcov.judge;

import java.util.ArrayList;
import java.util.List;

/**
 * A run that can step back as well as on, for a viewer: it keeps a checkpoint every
 * {@link #INTERVAL} ticks, and stepping back continues a copy of the last checkpoint before the
 * tick wanted up to it. The run stepped back to is the run as it was then, bit for bit. A run whose
 * controller cannot be copied steps only forward.
 */
public final class RunHistory {
    /** Ticks between checkpoints: a step back replays at most this many ticks. */
    static final int INTERVAL = 50;

    /** The k-th is the run after its first {@code k * INTERVAL} ticks. */
    private final List<LiveRun> checkpoints = new ArrayList<>();
    private LiveRun current;

    public RunHistory(LiveRun start) {
        this.current = start;
        if (start.copyable()) {
            checkpoints.add(start.copy());
        }
    }

    /** The run as it is now. */
    public LiveRun current() {
        return current;
    }

    /** Runs one tick; false once the run has ended. */
    public boolean step() {
        boolean goesOn = current.step();
        long done = current.tick() + 1;
        if (goesOn && current.copyable() && done % INTERVAL == 0 && checkpoints.size() == done / INTERVAL) {
            checkpoints.add(current.copy());
        }
        return goesOn;
    }

    /** Whether there is a tick to step back to. */
    public boolean canStepBack() {
        return current.copyable() && current.tick() >= 0;
    }

    /** Goes back to the run as it was a tick ago; false (and nothing changes) if it cannot. */
    public boolean stepBack() {
        if (!canStepBack()) {
            return false;
        }
        long wanted = current.tick() - 1;
        LiveRun replay = checkpoints.get((int) ((wanted + 1) / INTERVAL)).copy();
        while (replay.tick() < wanted) {
            replay.step();
        }
        current = replay;
        return true;
    }
}
