package sitcov.experiment;

import java.util.ArrayList;
import java.util.List;
import java.util.random.RandomGenerator;
import sitcov.faults.Fault;
import sitcov.stats.Bootstrap;
import sitcov.stats.ConfidenceInterval;
import sitcov.stats.Descriptive;
import sitcov.stats.EffectSize;
import sitcov.stats.FisherExact;
import sitcov.stats.Holm;
import sitcov.stats.MannWhitney;
import sitcov.stats.VarghaDelaney;
import sitcov.stats.WilcoxonSignedRank;

/**
 * Whether one driver beats another, the way the field reports it (Arcuri &amp; Briand): for every
 * pair of drivers (earlier against later in the preset), per measure over the paired replications,
 * the two means, the mean difference with a seeded bootstrap 95 % CI, the paired Wilcoxon
 * signed-rank p (replications share their candidate stream, so they are paired), the Mann-Whitney p
 * (as if independent, for comparison with studies that pool) and Vargha–Delaney Â12; per fault, the
 * maps finding it by each driver over all replications, Fisher's exact p, Holm-adjusted across the
 * faults of the pair, and the odds ratio with its CI. Everything under the differential oracle.
 */
public final class Comparison {
    /** The measures compared, each a value per driver and replication. */
    public enum Measure {
        CELLS_COVERED("cells_covered", "cells covered"),
        MAPS_RUN("maps_run", "maps run"),
        FAULTS_FOUND("faults_found", "distinct faults found"),
        AVG_MAP_FAULT("avg_map_fault", "faults found per map (avg-map-fault)"),
        PROP_MAP_ALL_FAULT("prop_map_all_fault", "share of maps finding every fault (prop-map-all-fault)"),
        DISCOVERY_AREA("discovery_area", "area under faults found against ticks");

        private final String key;
        private final String words;

        Measure(String key, String words) {
            this.key = key;
            this.words = words;
        }

        public String key() {
            return key;
        }

        public String words() {
            return words;
        }
    }

    /** One measure of one pair: A is the earlier driver; the difference is A minus B. */
    public record MeasureTest(Measure measure, String driverA, String driverB, int replications, double meanA,
                              double meanB, ConfidenceInterval difference, double pWilcoxon, double pMannWhitney,
                              double a12, EffectSize effect) {
    }

    /** One fault of one pair: maps finding it by each driver over all replications. */
    public record FaultTest(Fault fault, String driverA, String driverB, long foundA, long mapsA, long foundB, long mapsB,
                            double p, double pHolm, double oddsRatio, double oddsLow, double oddsHigh) {
    }

    private final List<MeasureTest> measures = new ArrayList<>();
    private final List<FaultTest> faults = new ArrayList<>();

    private Comparison() {
    }

    /** Every pair of drivers of {@code summary}, with bootstrap resamples drawn from {@code random}. */
    public static Comparison of(Summary summary, RandomGenerator random) {
        Comparison c = new Comparison();
        List<String> drivers = summary.drivers();
        for (int i = 0; i < drivers.size(); i++) {
            for (int j = i + 1; j < drivers.size(); j++) {
                c.compare(summary, drivers.get(i), drivers.get(j), random);
            }
        }
        return c;
    }

    public List<MeasureTest> measures() {
        return List.copyOf(measures);
    }

    public List<FaultTest> faults() {
        return List.copyOf(faults);
    }

    private void compare(Summary summary, String a, String b, RandomGenerator random) {
        for (Measure m : Measure.values()) {
            double[] x = values(summary, a, m);
            double[] y = values(summary, b, m);
            double a12 = VarghaDelaney.a12(x, y);
            measures.add(new MeasureTest(m, a, b, x.length, mean(x), mean(y), Bootstrap.pairedMeanDifference(x, y, random),
                    WilcoxonSignedRank.test(x, y).p(), MannWhitney.test(x, y).p(), a12, VarghaDelaney.magnitude(a12)));
        }
        List<Fault> list = summary.faults();
        long[][] counts = new long[list.size()][4];
        for (ReplicationResult r : summary.results()) {
            count(r.of(a), list, counts, 0);
            count(r.of(b), list, counts, 2);
        }
        double[] p = new double[list.size()];
        FisherExact.Result[] tests = new FisherExact.Result[list.size()];
        for (int f = 0; f < list.size(); f++) {
            long[] k = counts[f];
            tests[f] = FisherExact.test(k[0], k[1] - k[0], k[2], k[3] - k[2]);
            p[f] = tests[f].p();
        }
        double[] holm = Holm.adjust(p);
        for (int f = 0; f < list.size(); f++) {
            long[] k = counts[f];
            faults.add(new FaultTest(list.get(f), a, b, k[0], k[1], k[2], k[3], p[f], holm[f], tests[f].oddsRatio(),
                    tests[f].low(), tests[f].high()));
        }
    }

    private static void count(DriverRun run, List<Fault> faults, long[][] counts, int at) {
        for (MapRun map : run.maps()) {
            for (int f = 0; f < faults.size(); f++) {
                counts[f][at] += map.faults().get(f).found(false) ? 1 : 0;
                counts[f][at + 1]++;
            }
        }
    }

    /** The measure of {@code driver} in every replication, in replication order. */
    public static double[] values(Summary summary, String driver, Measure measure) {
        List<ReplicationResult> results = summary.results();
        double[] v = new double[results.size()];
        for (int r = 0; r < v.length; r++) {
            ReplicationResult rep = results.get(r);
            Metrics m = summary.metrics(rep.replication(), driver, false);
            v[r] = switch (measure) {
                case CELLS_COVERED -> m.cells();
                case MAPS_RUN -> m.maps();
                case FAULTS_FOUND -> m.faultsFound();
                case AVG_MAP_FAULT -> m.avgMapFault();
                case PROP_MAP_ALL_FAULT -> m.propMapAllFault();
                case DISCOVERY_AREA -> Discovery.of(rep.of(driver), summary.faults()).area(horizon(rep));
            };
        }
        return v;
    }

    /** Drivers of a replication are compared over the ticks the least spending one spent. */
    static long horizon(ReplicationResult replication) {
        return replication.drivers().stream().mapToLong(d -> d.spend().ticks()).min().orElse(0);
    }

    private static double mean(double[] v) {
        return Descriptive.mean(v);
    }
}
