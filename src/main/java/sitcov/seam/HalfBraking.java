package sitcov.seam;

import sitcov.control.Observation;

/**
 * The brakes bite at a fraction of their strength: where the world would slow the car, it slows it
 * by that fraction of the decrease asked for (after clamping). Speeding up is untouched.
 */
final class HalfBraking extends CommandDistortion {
    private double strength;
    private boolean braking;

    HalfBraking(double strength) {
        this.strength = strength;
    }

    @Override
    public boolean acting() {
        return braking;
    }

    @Override
    void distort(Motion asked, Observation real, Motion given) {
        given.of(asked);
        double current = real.speed();
        double wanted = asked.appliedSpeed(current);
        braking = wanted < current;
        if (braking) {
            given.speed = current - strength * (current - wanted);
        }
    }
}
