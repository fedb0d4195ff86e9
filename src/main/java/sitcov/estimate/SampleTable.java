package sitcov.estimate;

import java.util.ArrayList;
import java.util.EnumSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import sitcov.oracle.Failure;
import sitcov.world.DrawSite;
import sitcov.world.DrawTrace;

/**
 * samples.csv: one row per simulated map. Log-likelihoods and scores are written in full
 * ({@link Double#toString}), so the rows read back are the samples written, and an estimate made
 * from a merged folder is the one the unsharded run made.
 */
public final class SampleTable {
    private SampleTable() {
    }

    public static String header() {
        List<String> h = new ArrayList<>(List.of("replication", "stage", "index", "seed", "log_nominal", "log_proposal",
                "weight", "ticks", "score"));
        for (Failure f : Failure.values()) {
            h.add(f.column());
        }
        for (DrawSite s : DrawSite.values()) {
            h.add("bins_" + s.key());
        }
        return String.join(",", h);
    }

    public static String row(Sample s) {
        StringBuilder b = new StringBuilder();
        b.append(s.replication()).append(',').append(s.stage()).append(',').append(s.index()).append(',').append(s.seed())
                .append(',').append(s.trace().logNominal()).append(',').append(s.trace().logProposal()).append(',')
                .append(String.format(Locale.ROOT, "%.6g", s.weight())).append(',').append(s.ticks()).append(',')
                .append(s.score());
        for (Failure f : Failure.values()) {
            b.append(',').append(s.failures().contains(f) ? 1 : 0);
        }
        for (DrawSite site : DrawSite.values()) {
            b.append(',');
            for (int bin = 0; bin < site.bins(); bin++) {
                b.append(bin == 0 ? "" : " ").append(s.trace().draws(site, bin));
            }
        }
        return b.toString();
    }

    /**
     * The sample a row holds.
     *
     * @throws IllegalArgumentException naming what is wrong with it
     */
    public static Sample parse(String line) {
        String[] f = line.split(",", -1);
        int failures = Failure.values().length;
        int sites = DrawSite.values().length;
        if (f.length != 9 + failures + sites) {
            throw new IllegalArgumentException("a row has " + (9 + failures + sites) + " fields, this one " + f.length);
        }
        try {
            Set<Failure> failed = EnumSet.noneOf(Failure.class);
            for (Failure x : Failure.values()) {
                if (f[9 + x.ordinal()].equals("1")) {
                    failed.add(x);
                }
            }
            int[][] bins = new int[sites][];
            for (DrawSite s : DrawSite.values()) {
                String[] counts = f[9 + failures + s.ordinal()].split(" ");
                if (counts.length != s.bins()) {
                    throw new IllegalArgumentException("bins_" + s.key() + " holds " + counts.length + " counts, not " + s.bins());
                }
                bins[s.ordinal()] = new int[s.bins()];
                for (int b = 0; b < counts.length; b++) {
                    bins[s.ordinal()][b] = Integer.parseInt(counts[b]);
                }
            }
            DrawTrace trace = new DrawTrace(Double.parseDouble(f[4]), Double.parseDouble(f[5]), bins);
            return new Sample(Integer.parseInt(f[0]), f[1], Integer.parseInt(f[2]), Long.parseLong(f[3]), trace,
                    Long.parseLong(f[7]), Double.parseDouble(f[8]), failed);
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("a number is malformed (" + e.getMessage() + ")");
        }
    }
}
