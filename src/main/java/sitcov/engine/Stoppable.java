package sitcov.engine;

/** A handle on a repeating event; once stopped it never runs again. Stopping twice is harmless. */
@FunctionalInterface
public interface Stoppable {
    void stop();
}
