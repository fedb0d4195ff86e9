package sitcov.analysis;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.random.RandomGenerator;
import sitcov.experiment.DriverRun;
import sitcov.experiment.MapRun;
import sitcov.experiment.ReplicationResult;
import sitcov.judge.Variant;
import sitcov.judge.Notion;

/**
 * Situations against faults: which maps of each coverage cell found each fault (differential
 * oracle), over every distinct map an experiment ran (a map two drivers shared counts once), and a
 * test of the paper's uniformity hypothesis (§3.3: a cell is an equivalence class for fault
 * behaviour). For each fault, the share of the variance of "this map found it" that the cell
 * explains (η², between-cell over total sum of squares) is set against the same share when the maps
 * are dealt to cells of the same sizes at random: many small cells explain some variance by chance
 * alone, so only the excess over that null speaks for the hypothesis. The p-value is the share of
 * random deals explaining at least as much ((1 + count) / (1 + deals), so never 0).
 */
public final class SituationFaults {
    /** One fault's test: maps and finds, η² by cell, the mean η² of random deals, and the permutation p-value. */
    public record Uniformity(Variant variant, int maps, int found, double explained, double byChance, double p) {
    }

    private final List<Variant> faults;
    private final int[] cellOf;
    private final boolean[][] found;
    private final Map<Integer, int[]> matrix = new TreeMap<>();
    private final Map<Integer, Integer> mapsOfCell = new TreeMap<>();
    /** The cells seen, ascending: a cell's place here indexes the per-cell counts. */
    private final int[] dense;

    private SituationFaults(List<Variant> faults, int[] cellOf, boolean[][] found) {
        this.faults = faults;
        this.cellOf = cellOf;
        this.found = found;
        for (int m = 0; m < cellOf.length; m++) {
            int[] row = matrix.computeIfAbsent(cellOf[m], c -> new int[faults.size()]);
            mapsOfCell.merge(cellOf[m], 1, Integer::sum);
            for (int f = 0; f < faults.size(); f++) {
                row[f] += found[m][f] ? 1 : 0;
            }
        }
        dense = mapsOfCell.keySet().stream().mapToInt(Integer::intValue).toArray();
    }

    /** The distinct maps with a valid cell among the results, in the order first run. */
    public static SituationFaults of(List<ReplicationResult> results, List<Variant> faults) {
        Map<String, MapRun> distinct = new LinkedHashMap<>();
        for (ReplicationResult r : results) {
            for (DriverRun d : r.drivers()) {
                for (MapRun m : d.maps()) {
                    if (m.cell() >= 0) {
                        distinct.putIfAbsent(m.map().text() + "/" + m.internalSeed(), m);
                    }
                }
            }
        }
        List<MapRun> maps = new ArrayList<>(distinct.values());
        int[] cells = new int[maps.size()];
        boolean[][] found = new boolean[maps.size()][faults.size()];
        for (int m = 0; m < maps.size(); m++) {
            cells[m] = maps.get(m).cell();
            for (int f = 0; f < faults.size(); f++) {
                found[m][f] = maps.get(m).faults().get(f).found(Notion.DIFFERENTIAL);
            }
        }
        return new SituationFaults(List.copyOf(faults), cells, found);
    }

    public List<Variant> faults() {
        return faults;
    }

    /** Cells seen, ascending, each with its number of distinct maps. */
    public Map<Integer, Integer> mapsOfCell() {
        return java.util.Collections.unmodifiableMap(mapsOfCell);
    }

    /** Maps of {@code cell} that found each fault, in fault order. */
    public int[] foundIn(int cell) {
        return matrix.getOrDefault(cell, new int[faults.size()]).clone();
    }

    /** The uniformity test of every fault, with {@code deals} random deals drawn from {@code random}. */
    public List<Uniformity> uniformity(int deals, RandomGenerator random) {
        int n = cellOf.length;
        int[] dealt = cellOf.clone();
        double[][] chance = new double[faults.size()][deals];
        for (int d = 0; d < deals; d++) {
            for (int i = n - 1; i > 0; i--) {
                int j = random.nextInt(i + 1);
                int t = dealt[i];
                dealt[i] = dealt[j];
                dealt[j] = t;
            }
            for (int f = 0; f < faults.size(); f++) {
                chance[f][d] = explained(dealt, f);
            }
        }
        List<Uniformity> tests = new ArrayList<>();
        for (int f = 0; f < faults.size(); f++) {
            double observed = explained(cellOf, f);
            int atLeast = 0;
            double sum = 0;
            for (double c : chance[f]) {
                atLeast += c >= observed - 1e-12 ? 1 : 0;
                sum += c;
            }
            int finds = 0;
            for (boolean[] row : found) {
                finds += row[f] ? 1 : 0;
            }
            tests.add(new Uniformity(faults.get(f), n, finds, observed, deals == 0 ? Double.NaN : sum / deals,
                    (1.0 + atLeast) / (1.0 + deals)));
        }
        return tests;
    }

    /** η²: the between-cell share of the total sum of squares of the 0/1 "found" of fault {@code f}. */
    private double explained(int[] cells, int f) {
        int[] maps = new int[dense.length];
        int[] finds = new int[dense.length];
        int total = 0;
        for (int m = 0; m < cells.length; m++) {
            int g = denseIndex(cells[m]);
            maps[g]++;
            if (found[m][f]) {
                finds[g]++;
                total++;
            }
        }
        int n = cells.length;
        if (n == 0 || total == 0 || total == n) {
            return 0;
        }
        double mean = (double) total / n;
        double sumOfSquares = total * (1 - mean) * (1 - mean) + (n - total) * mean * mean;
        double between = 0;
        for (int g = 0; g < dense.length; g++) {
            if (maps[g] > 0) {
                double d = (double) finds[g] / maps[g] - mean;
                between += maps[g] * d * d;
            }
        }
        return between / sumOfSquares;
    }

    private int denseIndex(int cell) {
        return java.util.Arrays.binarySearch(dense, cell);
    }
}
