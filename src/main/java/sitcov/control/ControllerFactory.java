package sitcov.control;

/**
 * Makes the controller of one run: the builtin car with a set of faults, or a session with a
 * controller program. One factory serves every run of one worker thread.
 */
@FunctionalInterface
public interface ControllerFactory {
    Controller start(RunStart run);
}
