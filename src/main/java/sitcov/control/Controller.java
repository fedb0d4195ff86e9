package sitcov.control;

/**
 * The system under test: one run's driver of the car. The world calls {@link #step} once a tick, at
 * the car's turn among the vehicles (their order is shuffled every tick, so some may have moved
 * already); the controller reads the observation and fills the command.
 * Implementations: the builtin car (its faults are its variants) and a program speaking the
 * JSON-Lines protocol.
 */
public interface Controller {
    /** Decides this tick's command from what the car observes now; {@code out} arrives cleared. */
    void step(Observation now, Command out);

    /**
     * The sensors whose parts of the observation it takes, for viewers to draw (never for the world, which
     * offers every controller the same): a controller in process is handed them all, the default.
     */
    default java.util.Set<Sensor> sensors() {
        return Sensor.all();
    }

    /** The run is over (Target reached, timeout, or stopped); the default does nothing. */
    default void end(RunEnd how) {
    }
}
