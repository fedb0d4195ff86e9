package sitcov.analysis;

import java.util.ArrayList;
import java.util.List;
import sitcov.experiment.BudgetKind;
import sitcov.experiment.DriverRun;
import sitcov.experiment.MapRun;
import sitcov.experiment.Measure;
import sitcov.experiment.ReplicationResult;
import sitcov.judge.Variant;
import sitcov.judge.Notion;

/**
 * Two drivers of a comparison, replication by replication, as they are compared: under the ticks
 * budget each over the maps it had judged whole within the ticks both spent (the later driver of a
 * replication overshoots the first by up to one map, which the first never got), under a wall-clock
 * budget over everything each ran in the same time; the area under the discovery curve always to the
 * ticks both spent. So a pair's comparison depends on the pair alone, never on which other drivers ran.
 */
final class PairedReplications {
    private final String a;
    private final String b;
    private final double[][] measuresA;
    private final double[][] measuresB;
    private final long[][] foundA;
    private final long[][] foundB;
    private final long[] mapsA;
    private final long[] mapsB;

    private PairedReplications(String a, String b, int replications, int faults) {
        this.a = a;
        this.b = b;
        measuresA = new double[Measure.values().length][replications];
        measuresB = new double[Measure.values().length][replications];
        foundA = new long[faults][replications];
        foundB = new long[faults][replications];
        mapsA = new long[replications];
        mapsB = new long[replications];
    }

    static PairedReplications of(Summary summary, String a, String b, BudgetKind budget) {
        List<ReplicationResult> results = summary.results();
        List<Variant> faults = summary.faults();
        PairedReplications pair = new PairedReplications(a, b, results.size(), faults.size());
        for (int r = 0; r < results.size(); r++) {
            DriverRun runA = results.get(r).of(a);
            DriverRun runB = results.get(r).of(b);
            long horizon = Math.min(runA.spend().ticks(), runB.spend().ticks());
            pair.record(r, runA, horizon, budget, faults, pair.measuresA, pair.foundA, pair.mapsA);
            pair.record(r, runB, horizon, budget, faults, pair.measuresB, pair.foundB, pair.mapsB);
        }
        return pair;
    }

    private void record(int r, DriverRun run, long horizon, BudgetKind budget, List<Variant> faults, double[][] measures,
                        long[][] found, long[] maps) {
        List<MapRun> compared = budget == BudgetKind.TICKS ? within(run.maps(), horizon) : run.maps();
        Metrics m = Metrics.of(compared, faults, Notion.DIFFERENTIAL);
        double area = Discovery.of(run, faults).area(horizon);
        for (Measure measure : Measure.values()) {
            measures[measure.ordinal()][r] = switch (measure) {
                case OWN_FAILURES -> OwnFailures.count(compared);
                case DISTINCT_OWN_FAILURES -> OwnFailures.distinct(compared).size();
                default -> m.value(measure, area);
            };
        }
        maps[r] = compared.size();
        for (MapRun map : compared) {
            for (int f = 0; f < faults.size(); f++) {
                found[f][r] += map.faults().get(f).found(Notion.DIFFERENTIAL) ? 1 : 0;
            }
        }
    }

    /** The first maps whose ticks, counted from the start, end within {@code horizon}: judged whole by then. */
    static List<MapRun> within(List<MapRun> maps, long horizon) {
        List<MapRun> kept = new ArrayList<>();
        long ticks = 0;
        for (MapRun map : maps) {
            ticks += map.ticks();
            if (ticks > horizon) {
                break;
            }
            kept.add(map);
        }
        return kept;
    }

    String a() {
        return a;
    }

    String b() {
        return b;
    }

    int replications() {
        return mapsA.length;
    }

    double[] measureA(Measure m) {
        return measuresA[m.ordinal()].clone();
    }

    double[] measureB(Measure m) {
        return measuresB[m.ordinal()].clone();
    }

    /** Each replication's share of the first driver's compared maps that found fault {@code f} (0 without maps). */
    double[] shareA(int f) {
        return shares(foundA[f], mapsA);
    }

    double[] shareB(int f) {
        return shares(foundB[f], mapsB);
    }

    long[] foundA(int f) {
        return foundA[f].clone();
    }

    long[] foundB(int f) {
        return foundB[f].clone();
    }

    long[] mapsA() {
        return mapsA.clone();
    }

    long[] mapsB() {
        return mapsB.clone();
    }

    private static double[] shares(long[] found, long[] maps) {
        double[] s = new double[found.length];
        for (int r = 0; r < s.length; r++) {
            s[r] = maps[r] == 0 ? 0 : (double) found[r] / maps[r];
        }
        return s;
    }
}
