package sitcov.seam;

import sitcov.control.Command;
import sitcov.vehicles.Dynamics;

/**
 * The motion part of a command: a speed asked for outright (NaN when a change is asked instead), a
 * speed change and a steering angle. Junction requests and the self-report are not motion: seam
 * faults of the command leave them as the controller gave them.
 */
final class Motion {
    double speed = Double.NaN;
    double speedChange;
    double steering;

    void of(Command c) {
        speed = c.speed();
        speedChange = c.speedChange();
        steering = c.steering();
    }

    void of(Motion m) {
        speed = m.speed;
        speedChange = m.speedChange;
        steering = m.steering;
    }

    /** Keep the speed, straight on: what a car does before any command has arrived. */
    void hold() {
        speed = Double.NaN;
        speedChange = 0;
        steering = 0;
    }

    void into(Command c) {
        c.speedChange(speedChange).speed(speed).steering(steering);
    }

    /** The speed the world gives the car going {@code current} metres a tick (as it clamps it). */
    double appliedSpeed(double current) {
        double wanted = Double.isNaN(speed) ? current + speedChange : speed;
        return Math.max(0, Math.min(Dynamics.MAX_SPEED, Double.isNaN(wanted) ? current : wanted));
    }

    /** The turn the world carries out (as it clamps it). */
    double appliedSteering() {
        return Double.isNaN(steering) ? 0 : Math.max(-Dynamics.MAX_TURN, Math.min(Dynamics.MAX_TURN, steering));
    }

    /** Whether the world would carry out {@code other} otherwise than this, the car going {@code current}. */
    boolean appliesOtherwise(Motion other, double current) {
        return Double.compare(appliedSpeed(current), other.appliedSpeed(current)) != 0
                || Double.compare(appliedSteering(), other.appliedSteering()) != 0;
    }
}
