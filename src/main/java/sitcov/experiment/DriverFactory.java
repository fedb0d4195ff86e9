package sitcov.experiment;

/**
 * Makes the driver a preset names, fresh for each replication. The engine knows drivers only through
 * this; the drivers sitcov ships are registered in {@code sitcov.drivers.Drivers}.
 */
@FunctionalInterface
public interface DriverFactory {
    /**
     * A new driver named {@code name}.
     *
     * @throws IllegalArgumentException naming the drivers there are, when none is named so
     */
    Driver create(String name);
}
