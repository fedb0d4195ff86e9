package sitcov.seam;

import sitcov.control.Observation;

/** The steering actuator adds a fixed bias in degrees to every turn asked for (positive: to the left). */
final class SteeringBias extends CommandDistortion {
    private double degrees;

    SteeringBias(double degrees) {
        this.degrees = degrees;
    }

    @Override
    void distort(Motion asked, Observation real, Motion given) {
        given.of(asked);
        given.steering = (Double.isNaN(asked.steering) ? 0 : asked.steering) + degrees;
    }
}
