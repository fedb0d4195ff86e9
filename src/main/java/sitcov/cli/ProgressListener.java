package sitcov.cli;

import java.io.PrintStream;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.function.LongSupplier;
import sitcov.experiment.ExperimentEvent;
import sitcov.experiment.ExperimentListener;

/**
 * Progress of an experiment on stderr, updated per judged map: rewritten in place on a console,
 * otherwise at the first judged map and then a line every {@value #QUIET_SECONDS} s. The ETA estimates how long each driver's share
 * of a replication takes (from the shares finished, else from the one in progress) and deals the
 * remaining replications to the threads, so the last replication running alone is foreseen.
 */
final class ProgressListener implements ExperimentListener {
    static final int QUIET_SECONDS = 15;

    private final PrintStream err;
    private final boolean console;
    private final LongSupplier nanoClock;
    private final long start;
    private final Map<Integer, Unit> running = new HashMap<>();
    private double[] doneSeconds = new double[0];
    private int[] doneCount = new int[0];
    private int drivers;
    private int threads;
    private int replications;
    private int finished;
    private int maps;
    private String name = "";
    private long lastPrint;
    /** Whether a map was simulated yet: while a resumed run replays its journal, times say nothing. */
    private boolean live;

    /** The driver a replication is at, how far through it is, and how long it had run when last heard of. */
    private static final class Unit {
        int driver;
        double share;
        double seconds;
        long heard;
    }

    ProgressListener(PrintStream err, boolean console, LongSupplier nanoClock) {
        this.err = err;
        this.console = console;
        this.nanoClock = nanoClock;
        this.start = nanoClock.getAsLong();
        this.lastPrint = start;
    }

    @Override
    public void on(ExperimentEvent event) {
        long now = nanoClock.getAsLong();
        if (event instanceof ExperimentEvent.Started s) {
            drivers = s.config().drivers().size();
            threads = s.threads();
            replications = s.replications().size();
            name = s.config().name();
            doneSeconds = new double[drivers];
            doneCount = new int[drivers];
            return;
        }
        if (event instanceof ExperimentEvent.MapJudged m) {
            Unit u = unit(m.run().replication(), now);
            u.driver = m.driverIndex();
            u.share = m.share();
            u.seconds = m.driverNanos() / 1e9;
            u.heard = now;
            maps++;
            live |= !m.resumed();
        } else if (event instanceof ExperimentEvent.DriverDone d) {
            doneSeconds[d.driverIndex()] += d.driverNanos() / 1e9;
            doneCount[d.driverIndex()]++;
            Unit u = unit(d.spend().replication(), now);
            u.driver = d.driverIndex() + 1;
            u.share = 0;
            u.seconds = 0;
            u.heard = now;
        } else if (event instanceof ExperimentEvent.ReplicationDone r) {
            running.remove(r.replication());
            finished++;
        }
        boolean end = event instanceof ExperimentEvent.Ended;
        if (end || (console ? now - lastPrint > 200_000_000L : now - lastPrint > QUIET_SECONDS * 1_000_000_000L)
                || event instanceof ExperimentEvent.ReplicationDone || (event instanceof ExperimentEvent.MapJudged && maps == 1)) {
            lastPrint = now;
            print(now, end);
        }
    }

    private Unit unit(int replication, long now) {
        return running.computeIfAbsent(replication, r -> new Unit());
    }

    private void print(long now, boolean end) {
        double elapsed = (now - start) / 1e9;
        double eta = end ? 0 : eta(now);
        String line = String.format(Locale.ROOT, "run %s: %d/%d replications done, %d maps judged, %s elapsed, %s", name,
                finished, replications, maps, Progress.duration(elapsed), Double.isNaN(eta) ? "ETA: estimating" : "ETA " + Progress.duration(eta));
        if (console) {
            err.print("\r" + line + "   " + (end ? System.lineSeparator() : ""));
            err.flush();
        } else {
            err.println(line);
        }
    }

    /** Seconds until the last replication ends, or NaN while nothing tells how long a driver takes. */
    double eta(long now) {
        if (!live) {
            return Double.NaN;
        }
        double[] est = new double[drivers];
        for (int d = 0; d < drivers; d++) {
            est[d] = estimate(d, now);
            if (Double.isNaN(est[d]) && d > 0) {
                est[d] = est[0];
            }
            if (Double.isNaN(est[d])) {
                return Double.NaN;
            }
        }
        double whole = Arrays.stream(est).sum();
        List<Double> busy = new ArrayList<>();
        for (Unit u : running.values()) {
            double left = 0;
            for (int d = u.driver; d < drivers; d++) {
                left += d == u.driver ? Math.max(0, est[d] * (1 - u.share) - (now - u.heard) / 1e9) : est[d];
            }
            busy.add(left);
        }
        double[] free = new double[Math.max(threads, busy.size())];
        for (int i = 0; i < busy.size(); i++) {
            free[i] = busy.get(i);
        }
        for (int r = finished + running.size(); r < replications; r++) {
            int soonest = 0;
            for (int i = 1; i < free.length; i++) {
                soonest = free[i] < free[soonest] ? i : soonest;
            }
            free[soonest] += whole;
        }
        return Arrays.stream(free).max().orElse(0);
    }

    /** Seconds one share of driver {@code d} takes: the mean of finished ones, else extrapolated from those running. */
    private double estimate(int d, long now) {
        if (doneCount[d] > 0) {
            return doneSeconds[d] / doneCount[d];
        }
        List<Double> guesses = new ArrayList<>();
        for (Unit u : running.values()) {
            if (u.driver == d && u.share >= 0.01) {
                guesses.add(u.seconds / u.share);
            }
        }
        if (guesses.isEmpty()) {
            return Double.NaN;
        }
        guesses.sort(null);
        return guesses.get(guesses.size() / 2);
    }

    String elapsed() {
        return Progress.duration((nanoClock.getAsLong() - start) / 1e9);
    }
}
