package sitcov.engine;

/** Something the {@link Schedule} can run at a tick: a vehicle, a detector, a one-off event. */
@FunctionalInterface
public interface Steppable {
    void step(SimState state);
}
