package sitcov.experiment;

/** What one driver spent in one replication, and why it stopped. Nothing timed: timings are kept apart. */
public record DriverSpend(int replication, String driver, int candidates, int mapsRun, long ticks, int cellsCovered,
                          StopReason stoppedBy) {
}
