package sitcov.judge;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import sitcov.control.ControllerBatch;
import sitcov.control.ControllerFactory;

/**
 * Runs stepped together on the calling thread, over a {@link ControllerBatch}: each slot holds one
 * run at a time; every run is stepped until its controller has taken the tick's observation (the
 * tick pauses there), one exchange answers them all, and the ticks resume. A slot whose run ends
 * takes the next. No thread waits on another, and the runs are those they would have been alone.
 */
public final class BatchedRuns {
    /** Makes run {@code index} with the controllers of the slot it is given. */
    @FunctionalInterface
    public interface RunMaker {
        LiveRun start(int index, ControllerFactory controller);
    }

    private BatchedRuns() {
    }

    /**
     * Runs {@code count} runs, {@code batch.size()} at a time; their records in the order of their
     * index. The slots are stepped in two halves: one half's observations go out, and its runs wait
     * for their answer while the other half is stepped, so sitcov and the controller work at once.
     */
    public static List<RunRecord> run(int count, ControllerBatch batch, RunMaker runs) {
        List<RunRecord> records = new ArrayList<>(Collections.nCopies(count, null));
        int slots = Math.min(batch.size(), count);
        LiveRun[] held = new LiveRun[slots];
        int[] index = new int[slots];
        int next = 0;
        for (int s = 0; s < slots; s++) {
            index[s] = next;
            held[s] = runs.start(next++, batch.slot(s));
        }
        int halves = slots >= 2 ? 2 : 1;
        int[] bounds = {0, (slots + 1) / 2, slots};
        if (halves == 1) {
            bounds[1] = slots;
        }
        boolean[] sent = new boolean[halves];
        int live = slots;
        while (live > 0) {
            for (int h = 0; h < halves; h++) {
                if (sent[h]) {
                    batch.receive();
                    sent[h] = false;
                }
                boolean waiting = false;
                for (int s = bounds[h]; s < bounds[h + 1]; s++) {
                    while (held[s] != null) {
                        LiveRun.Progress p = held[s].advance();
                        if (p == LiveRun.Progress.AWAITING_COMMAND) {
                            waiting = true;
                            break;
                        }
                        if (p == LiveRun.Progress.ENDED) {
                            records.set(index[s], held[s].record());
                            held[s] = null;
                            if (next < count) {
                                index[s] = next;
                                held[s] = runs.start(next++, batch.slot(s));
                            } else {
                                live--;
                            }
                        }
                    }
                }
                if (waiting) {
                    batch.send();
                    sent[h] = true;
                }
            }
        }
        return records;
    }
}
