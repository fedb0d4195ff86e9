package sitcov.control;

/**
 * Makes the controller of one run: the builtin car, a Java controller, or a session with a
 * controller program. One factory serves every run of one worker thread. A controller with seeded
 * faults is made by a factory that is also handed the run's faults ({@code faults.SeededControllerFactory}).
 */
@FunctionalInterface
public interface ControllerFactory {
    Controller start(RunStart run);

    /**
     * Whether its controllers keep all their state in objects of the run, so that a checkpoint of
     * the run copies them too and a faulty run can be forked from the fault-free one (the builtin
     * car). A controller in another process cannot be copied: its runs are run whole.
     */
    default boolean copyable() {
        return false;
    }

    /** The same controllers, each run run whole, never forked from a checkpoint ({@code --fork off}). */
    default ControllerFactory unforked() {
        return this::start;
    }
}
