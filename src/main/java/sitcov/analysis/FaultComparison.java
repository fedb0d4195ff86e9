package sitcov.analysis;

import sitcov.judge.Variant;

/**
 * One fault of one pair of drivers: each replication's share of a driver's maps finding it, compared
 * pair by pair ({@code paired}); how clustered each driver's finds are over replications (Pearson
 * dispersion, about 1 when they are not); and, as description only, the maps of all replications
 * pooled: finds and maps of each driver, Fisher's exact p and the odds ratio with its CI (NaN where
 * the fault was not testable, as an odds ratio of nothing against nothing says nothing).
 */
public record FaultComparison(Variant variant, String driverA, String driverB, PairedDifference paired, double dispersionA,
                              double dispersionB, long foundA, long mapsA, long foundB, long mapsB, double pFisher,
                              double oddsRatio, double oddsLow, double oddsHigh, Finding finding, String note) {
}
