package sitcov.experiment;

import java.util.List;

/** Every driver's share of one replication (or one map set of a sweep), in the preset's driver order. */
public record ReplicationResult(int replication, List<DriverRun> drivers) {
    public ReplicationResult {
        drivers = List.copyOf(drivers);
    }

    public DriverRun of(String driver) {
        return drivers.stream().filter(d -> d.driver().equals(driver)).findFirst()
                .orElseThrow(() -> new IllegalArgumentException("no driver '" + driver + "' in replication " + replication));
    }
}
