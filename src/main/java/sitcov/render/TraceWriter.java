package sitcov.render;

import java.io.BufferedWriter;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.Locale;
import sitcov.judge.RunObserver;
import sitcov.oracle.AccidentDetector;
import sitcov.results.OutputFile;
import sitcov.control.Vehicle;
import sitcov.vehicles.Telemetry;

/**
 * Writes a run tick by tick as CSV (UTF-8, '\n' line ends, a header row): both seeds, the tick,
 * the autonomous car's pose, speed, lane, overtaking stage, junction flags, the behaviour that
 * steered it, and the accidents so far. Numbers have a fixed, locale-independent format, so the
 * same run always gives the same bytes. Rows go to a temporary file beside the target, which
 * {@link #close()} moves into place, so a reader never sees half a trace.
 */
public final class TraceWriter implements RunObserver, AutoCloseable {
    public static final String HEADER = "external_seed,internal_seed,tick,x,y,heading,speed,lane,overtaking_stage,"
            + "crossing_junction,waiting_at_junction,steered_by,accidents_so_far";

    private final Path target;
    private final OutputFile file;
    private final BufferedWriter out;
    private final String seeds;
    private final StringBuilder row = new StringBuilder(128);
    private boolean closed;
    private boolean failed;

    public TraceWriter(Path file, long externalSeed, long internalSeed) throws IOException {
        this.target = file.toAbsolutePath();
        this.file = OutputFile.open(target);
        this.seeds = externalSeed + "," + internalSeed + ",";
        try {
            this.out = new BufferedWriter(new java.io.OutputStreamWriter(this.file.stream(), StandardCharsets.UTF_8));
            out.write(HEADER);
            out.write('\n');
        } catch (IOException | RuntimeException e) {
            this.file.close();
            throw e;
        }
    }

    @Override
    public void afterTick(long tick, Telemetry run, AccidentDetector detector) {
        if (closed) {
            throw new IllegalStateException("the trace " + target + " is already closed");
        }
        Vehicle car = run.car();
        row.setLength(0);
        row.append(seeds).append(tick).append(',')
                .append(number(car.x())).append(',')
                .append(number(car.y())).append(',')
                .append(number(car.heading())).append(',')
                .append(number(car.speed())).append(',')
                .append(run.selfReport().lane()).append(',')
                .append(run.selfReport().stage()).append(',')
                .append(run.selfReport().crossingJunction()).append(',')
                .append(run.selfReport().waitingAtJunction()).append(',')
                .append(text(run.selfReport().steeredBy())).append(',')
                .append(detector.accidents().size()).append('\n');
        try {
            out.append(row);
        } catch (IOException e) {
            failed = true;
            throw new UncheckedIOException("cannot write the trace " + target, e);
        }
    }

    /** Finishes the file and moves it into place; a second call does nothing. */
    @Override
    public void close() throws IOException {
        if (closed) {
            return;
        }
        closed = true;
        try {
            out.flush();
            if (failed) {
                throw new IOException("the trace " + target + " was not written completely");
            }
            file.commit();
        } finally {
            file.close();
        }
    }

    private static String number(double v) {
        String s = String.format(Locale.ROOT, "%.4f", v);
        return s.equals("-0.0000") ? "0.0000" : s;
    }

    /** A free-text field: empty when absent, quoted when it holds a comma, quote or line break. */
    private static String text(String s) {
        if (s == null) {
            return "";
        }
        if (s.indexOf(',') < 0 && s.indexOf('"') < 0 && s.indexOf('\n') < 0 && s.indexOf('\r') < 0) {
            return s;
        }
        return '"' + s.replace("\"", "\"\"") + '"';
    }
}
