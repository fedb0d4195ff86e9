package sitcov.render;

import java.io.BufferedWriter;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.Locale;
import sitcov.judge.RunObserver;
import sitcov.oracle.AccidentDetector;
import sitcov.oracle.AccidentType;
import sitcov.oracle.Margins;
import sitcov.oracle.NearMiss;
import sitcov.oracle.NearMisses;
import sitcov.results.OutputFile;
import sitcov.control.Vehicle;
import sitcov.vehicles.Telemetry;

/**
 * Writes a run tick by tick as CSV (UTF-8, '\n' line ends, a header row): both seeds, the tick,
 * the autonomous car's pose, speed, lane, overtaking stage, junction flags, the behaviour that
 * steered it, and the accidents so far; then how close the run has come to each accident so far: each
 * near-miss measure's least value up to this tick and each accident type's robustness ρ so far
 * ({@link NearMisses}: the watcher keeps least-so-far values, which are exact; a tick's own gaps it
 * skips where they cannot beat the least). These are runs.csv's near_* and rho_* columns, written the
 * same way (4 decimals, "inf" never met, empty unknown), so the last row holds the run's values.
 * Numbers have a fixed, locale-independent format, so the
 * same run always gives the same bytes. Rows go to a temporary file beside the target, which
 * {@link #close()} moves into place, so a reader never sees half a trace.
 */
public final class TraceWriter implements RunObserver, AutoCloseable {
    /** The columns before the near misses, as they were before near misses were traced. */
    static final String POSE_HEADER = "external_seed,internal_seed,tick,x,y,heading,speed,lane,overtaking_stage,"
            + "crossing_junction,waiting_at_junction,steered_by,accidents_so_far";
    public static final String HEADER = POSE_HEADER + marginColumns();

    private final Path target;
    private final OutputFile file;
    private final BufferedWriter out;
    private final String seeds;
    private final StringBuilder row = new StringBuilder(256);
    private final NearMissWatch nearMisses = new NearMissWatch();
    private final boolean clamps;
    private boolean closed;
    private boolean failed;

    public TraceWriter(Path file, long externalSeed, long internalSeed) throws IOException {
        this(file, externalSeed, internalSeed, false);
    }

    /**
     * @param clamps whether to end each row with a {@code clamped} column: what the world clamped in
     *               the tick's command (asked and given), empty when nothing; for controllers other
     *               than the builtin car, whose traces keep the columns they always had
     */
    public TraceWriter(Path file, long externalSeed, long internalSeed, boolean clamps) throws IOException {
        this.clamps = clamps;
        this.target = file.toAbsolutePath();
        this.file = OutputFile.open(target);
        this.seeds = externalSeed + "," + internalSeed + ",";
        try {
            this.out = new BufferedWriter(new java.io.OutputStreamWriter(this.file.stream(), StandardCharsets.UTF_8));
            out.write(HEADER);
            out.write(clamps ? ",clamped\n" : "\n");
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
                .append(detector.accidents().size());
        nearMisses.afterTick(tick, run, detector);
        NearMisses watched = nearMisses.nearMisses();
        for (NearMiss m : NearMiss.values()) {
            row.append(',').append(margin(watched.least(m)));
        }
        for (AccidentType t : AccidentType.values()) {
            row.append(',').append(margin(watched.robustness(t)));
        }
        if (clamps) {
            row.append(',').append(run.clamped() ? text(run.clampNote()) : "");
        }
        row.append('\n');
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

    private static String marginColumns() {
        StringBuilder s = new StringBuilder();
        for (NearMiss m : NearMiss.values()) {
            s.append(',').append(m.column());
        }
        for (AccidentType t : AccidentType.values()) {
            s.append(',').append(t.robustnessColumn());
        }
        return s.toString();
    }

    /** A margin as runs.csv writes it (see experiments/README.md, "The results folder"): kept decimals, "inf", empty unknown. */
    private static String margin(double v) {
        double kept = Margins.kept(v);
        if (Double.isNaN(kept)) {
            return "";
        }
        if (Double.isInfinite(kept)) {
            return kept > 0 ? "inf" : "-inf";
        }
        return String.format(Locale.ROOT, "%." + Margins.DECIMALS + "f", kept); // as runs.csv has it, "-0.0000" too
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
