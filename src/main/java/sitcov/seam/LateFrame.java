package sitcov.seam;

/**
 * Every observation arrives late: in tick t the controller is handed the frame of tick t − k (of
 * tick 0 while t < k), remembered as it was. The frames of the last k ticks are kept in a ring.
 */
final class LateFrame extends FrameView {
    private int late;
    private Frame[] ring;
    private Frame shown;

    LateFrame(int late) {
        this.late = late;
        this.ring = new Frame[late + 1];
        for (int i = 0; i < ring.length; i++) {
            ring[i] = new Frame();
        }
    }

    @Override
    void started() {
        long from = Math.max(0, tick - late);
        shown = from == tick ? null : ring[(int) (from % ring.length)];
    }

    @Override
    Frame shown() {
        return shown;
    }

    @Override
    void endTick(Consults consulted) {
        // frame 0 stays shown until tick k: it must not be written over before then
        ring[(int) (tick % ring.length)].remember(real, consulted.ever());
    }
}
