package sitcov.cli;

import java.io.PrintStream;
import java.util.Locale;
import java.util.function.LongSupplier;

/**
 * Progress of a long loop on stderr: rewritten in place with '\r' on a console, otherwise one
 * line every 10%. The clock only feeds the ETA; nothing timed reaches stdout.
 */
final class Progress {
    private final PrintStream err;
    private final String what;
    private final int total;
    private final boolean console;
    private final LongSupplier nanoClock;
    private final long start;
    private int lastDecile;

    Progress(PrintStream err, String what, int total, boolean console, LongSupplier nanoClock) {
        this.err = err;
        this.what = what;
        this.total = total;
        this.console = console;
        this.nanoClock = nanoClock;
        this.start = nanoClock.getAsLong();
    }

    void done(int done) {
        int decile = (int) (10L * done / total);
        if (!console && decile == lastDecile) {
            return;
        }
        lastDecile = decile;
        double elapsed = (nanoClock.getAsLong() - start) / 1e9;
        double eta = done == 0 ? 0 : elapsed * (total - done) / done;
        String line = String.format(Locale.ROOT, "%s: %d/%d (%d%%), %s elapsed, ETA %s", what, done, total,
                100L * done / total, duration(elapsed), duration(eta));
        if (console) {
            err.print("\r" + line + "   " + (done == total ? System.lineSeparator() : ""));
            err.flush();
        } else {
            err.println(line);
        }
    }

    static String duration(double seconds) {
        long s = Math.round(seconds);
        return s < 60 ? s + " s" : String.format(Locale.ROOT, "%d min %02d s", s / 60, s % 60);
    }
}
