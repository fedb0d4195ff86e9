package sitcov.seam;

import sitcov.control.Observation;

/**
 * Every command's motion is carried out late: in tick t the world gets the motion asked for in tick
 * t − k; before tick k it keeps the car's speed and steers straight on. Junction requests go through
 * at once. The motions of the last k ticks are kept in a ring.
 */
final class LateCommand extends CommandDistortion {
    private int late;
    private Motion[] ring;

    LateCommand(int late) {
        this.late = late;
        this.ring = new Motion[late + 1];
        for (int i = 0; i < ring.length; i++) {
            ring[i] = new Motion();
        }
    }

    @Override
    void distort(Motion asked, Observation real, Motion given) {
        if (tick < late) {
            given.hold();
        } else {
            given.of(ring[(int) ((tick - late) % ring.length)]);
        }
        ring[(int) (tick % ring.length)].of(asked);
    }
}
