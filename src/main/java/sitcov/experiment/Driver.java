package sitcov.experiment;

/**
 * A test generator: it draws or builds situations, decides which to run, and is charged for what
 * it spends. Each replication gets a fresh instance, so a driver may keep state; it must take
 * every random choice from the session, whose streams are seeded by the experiment.
 *
 * <p>To add one, implement this interface and register its name in
 * {@code sitcov.drivers.Drivers.standard()}, which the engine reaches only as a {@link DriverFactory}.
 */
@FunctionalInterface
public interface Driver {
    /** Draws candidates and runs maps through {@code session} until {@link DriverSession#budgetLeft()} is false. */
    void drive(DriverSession session);

    /**
     * How far through its share of the replication the driver is, 0..1, for the progress display
     * only (results never depend on it). By default, the share of its budget it has spent.
     */
    default double progress(DriverSession session) {
        return session.budgetSpent();
    }
}
