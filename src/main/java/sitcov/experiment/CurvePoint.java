package sitcov.experiment;

/** Coverage reached by a driver after a number of candidates, maps run, simulated ticks and (not reproducible) seconds. */
public record CurvePoint(Method method, int replication, int candidates, int mapsRun, long ticks, int cellsCovered,
                         double seconds) {
}
