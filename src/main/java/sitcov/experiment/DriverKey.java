package sitcov.experiment;

/** One driver's part of one replication: the key of its maps and its spend in the journal and its tables. */
public record DriverKey(int replication, String driver) {
    public DriverKey {
        if (driver == null) {
            throw new IllegalArgumentException("a driver key needs a driver");
        }
    }

    public static DriverKey of(MapRun run) {
        return new DriverKey(run.replication(), run.driver());
    }

    public static DriverKey of(DriverSpend spend) {
        return new DriverKey(spend.replication(), spend.driver());
    }
}
