package sitcov.analysis;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.random.RandomGenerator;
import sitcov.experiment.DriverRun;
import sitcov.experiment.MapRun;
import sitcov.experiment.ReplicationResult;
import sitcov.oracle.AccidentType;
import sitcov.stats.Bootstrap;
import sitcov.stats.ConfidenceInterval;
import sitcov.stats.McNemar;

/**
 * The reference's own failures a test suite found: maps on which the reference run had an accident or
 * its controller failed (no variant involved). Per driver: how many, per million simulated ticks (all the
 * ticks it spent, faulty runs included, as every driver is charged), and how many distinct ones (a
 * cell × accident type counted once), in each replication and over all of them pooled. Each other
 * driver is compared with the reference driver (random, when there is one) by a sign test on the
 * replications' rates (McNemar's exact form): a replication counts for the driver whose rate is
 * higher, ties not at all, so failures found in bursts weigh no more than one replication; and the
 * ratio of its pooled rate to the reference driver's gets a bootstrap interval over replications,
 * which widens as it should when one replication holds most of the failures.
 */
public record OwnFailures(List<Failure> failures, List<DriverRate> rates) {
    /** One map on which the fault-free car failed. */
    public record Failure(int replication, String driver, int mapIndex, MapRun run, List<sitcov.oracle.Failure> types) {
    }

    /**
     * One driver's own failures: in all, per million ticks, distinct per replication (mean) and pooled;
     * {@code higher}/{@code lower} replications than the reference driver, and the sign test's p (NaN
     * for the reference itself); its rate over the reference driver's with a 95 % bootstrap interval
     * over replications ({@link Bootstrap#NOTHING} for the reference itself).
     */
    public record DriverRate(String driver, long failures, long ticks, double perMillionTicks, double distinctMean,
                             long distinctPooled, int higher, int lower, double p, ConfidenceInterval ratio) {
    }

    public OwnFailures {
        failures = List.copyOf(failures);
        rates = List.copyOf(rates);
    }

    /**
     * The failures of every driver in {@code drivers}' order, compared with {@code reference}; the rate
     * ratios' intervals resample replications with {@code random}.
     */
    public static OwnFailures of(List<ReplicationResult> results, List<String> drivers, String reference,
                                 RandomGenerator random) {
        List<Failure> all = new ArrayList<>();
        for (ReplicationResult r : results) {
            for (String d : drivers) {
                for (MapRun m : r.of(d).maps()) {
                    List<sitcov.oracle.Failure> types = types(m);
                    if (!types.isEmpty()) {
                        all.add(new Failure(r.replication(), d, m.mapIndex(), m, types));
                    }
                }
            }
        }
        List<DriverRate> rates = new ArrayList<>();
        for (String d : drivers) {
            long failures = 0;
            long ticks = 0;
            double distinct = 0;
            Set<Long> pooled = new HashSet<>();
            int higher = 0;
            int lower = 0;
            int n = results.size();
            double[] found = new double[n];
            double[] spent = new double[n];
            double[] theirFound = new double[n];
            double[] theirSpent = new double[n];
            for (int i = 0; i < n; i++) {
                ReplicationResult r = results.get(i);
                DriverRun run = r.of(d);
                Set<Long> here = new HashSet<>();
                long failed = 0;
                for (MapRun m : run.maps()) {
                    List<sitcov.oracle.Failure> types = types(m);
                    for (sitcov.oracle.Failure t : types) {
                        long key = (long) m.cell() * sitcov.oracle.Failure.values().length + t.ordinal();
                        here.add(key);
                        pooled.add(key);
                    }
                    failed += types.isEmpty() ? 0 : 1;
                }
                failures += failed;
                ticks += run.spend().ticks();
                distinct += here.size();
                found[i] = failed;
                spent[i] = run.spend().ticks();
                theirFound[i] = count(r.of(reference));
                theirSpent[i] = r.of(reference).spend().ticks();
                double rate = rate(failed, run.spend().ticks());
                double theirs = rate(count(r.of(reference)), r.of(reference).spend().ticks());
                higher += rate > theirs ? 1 : 0;
                lower += rate < theirs ? 1 : 0;
            }
            rates.add(new DriverRate(d, failures, ticks, rate(failures, ticks), results.isEmpty() ? 0 : distinct / results.size(),
                    pooled.size(), higher, lower, d.equals(reference) ? Double.NaN : McNemar.exactP(higher, lower),
                    d.equals(reference) ? Bootstrap.NOTHING
                            : Bootstrap.pairedRateRatio(found, spent, theirFound, theirSpent, random)));
        }
        return new OwnFailures(all, rates);
    }

    private static long count(DriverRun run) {
        return count(run.maps());
    }

    /** Maps of {@code maps} whose reference run failed. */
    static long count(List<MapRun> maps) {
        return maps.stream().filter(m -> !types(m).isEmpty()).count();
    }

    /** The distinct own failures of {@code maps}: each cell × failure type once. */
    static Set<Long> distinct(List<MapRun> maps) {
        Set<Long> keys = new HashSet<>();
        for (MapRun m : maps) {
            for (sitcov.oracle.Failure t : types(m)) {
                keys.add((long) m.cell() * sitcov.oracle.Failure.values().length + t.ordinal());
            }
        }
        return keys;
    }

    private static double rate(long failures, long ticks) {
        return ticks == 0 ? 0 : failures * 1e6 / ticks;
    }

    /** Whether the map's reference run failed by itself: an accident, or its controller's failure. */
    public static boolean failed(MapRun m) {
        return !types(m).isEmpty();
    }

    /** How the map's reference run failed: its accident types in type order, then its controller's failure if any. */
    public static List<sitcov.oracle.Failure> types(MapRun m) {
        List<sitcov.oracle.Failure> types = new ArrayList<>();
        for (AccidentType t : AccidentType.values()) {
            if (m.faultFree().count(t) > 0) {
                types.add(sitcov.oracle.Failure.of(t));
            }
        }
        sitcov.oracle.Failure.of(m.faultFree().outcome()).ifPresent(types::add);
        return types;
    }
}
