package sitcov.seam;

import java.util.random.RandomGenerator;
import sitcov.control.Observation;

/**
 * From time to time the steering sticks: each tick, unless it is stuck already, it sticks with the
 * fault's chance (drawn from its stream), and for the fault's number of ticks the world turns the car
 * by the turn it carried out in the tick before, whatever the controller asks.
 */
final class SteeringStuck extends CommandDistortion {
    private RandomGenerator draws;
    private double chance;
    private int ticks;
    private int left;
    private boolean stuck;
    private double stuckAt;
    private double lastTurn;

    SteeringStuck(RandomGenerator draws, double chance, int ticks) {
        this.draws = draws;
        this.chance = chance;
        this.ticks = ticks;
    }

    @Override
    void started() {
        if (left > 0) {
            left--;
            stuck = true;
        } else {
            stuck = draws.nextDouble() < chance;
            if (stuck) {
                left = ticks - 1;
                stuckAt = lastTurn;
            }
        }
    }

    @Override
    public boolean acting() {
        return stuck;
    }

    @Override
    void distort(Motion asked, Observation real, Motion given) {
        given.of(asked);
        if (stuck) {
            given.steering = stuckAt;
        }
    }

    @Override
    void handed(Motion motion) {
        lastTurn = motion.appliedSteering();
    }
}
