package sitcov.results;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import sitcov.experiment.ExperimentConfig;
import sitcov.experiment.MapId;
import sitcov.experiment.MapRun;
import sitcov.judge.Variant;
import sitcov.judge.Detection;
import sitcov.judge.FaultOutcome;
import sitcov.judge.RunSummary;
import sitcov.oracle.AccidentType;
import sitcov.oracle.Failure;
import sitcov.oracle.Margins;
import sitcov.oracle.NearMiss;
import sitcov.oracle.Outcome;

/**
 * {@code runs.csv}: one row per simulated run, a block per judged map (its fault-free row, then one
 * row per fault in id order). Nothing timed is in it. Reading it back gives the same maps, so a
 * resumed or merged experiment is computed from exactly what an uninterrupted one writes. Its
 * columns depend on the experiment (one per criterion of its grid); {@link #columns()} lists them,
 * and rows are written and read by those names.
 */
public final class RunsCsv {
    private static final String NO_FAULT = "NONE";
    private static final String FAULT = "fault";
    private static final String REACHED = "reached";
    private static final String EFFECTIVE = "effective";
    private static final String FIRST_EFFECTIVE_TICK = "first_effective_tick";
    private static final String DETECTION = "detection";
    private static final String NEW_ACCIDENT = "new_accident";
    private static final String PAPER_FOUND = "paper_found";
    /** Why the run's controller failed: only in folders of experiments whose controllers could fail. */
    private static final String CONTROLLER_FAILURE = "controller_failure";
    /** How many ticks' commands the world clamped: beside controller_failure, in the same folders. */
    private static final String CLAMPED_TICKS = "clamped_ticks";
    /** A reason is kept to this many characters, on one line and without commas. */
    private static final int REASON_CHARS = 240;
    /** The columns only a faulty run has: empty in the fault-free row. */
    private static final List<String> FAULT_ONLY =
            List.of(REACHED, EFFECTIVE, FIRST_EFFECTIVE_TICK, DETECTION, NEW_ACCIDENT, PAPER_FOUND);

    private final List<Variant> faults;
    /** The columns naming the map, the same in every row of its block. */
    private final List<String> mapColumns;
    private final List<String> criteria;
    private final Columns columns;
    private final boolean reasons;

    public RunsCsv(ExperimentConfig config) {
        // the builtin car in process cannot fail as a controller: its folders keep the columns they always had
        this.reasons = !config.onBuiltinFaults();
        this.faults = config.variants();
        this.criteria = config.grid().criteria().stream().map(c -> c.key().replace('-', '_')).toList();
        List<String> map = new ArrayList<>(List.of("replication", "driver", "map_index", "candidate", "map",
                "external_seed", "internal_seed", "cell"));
        map.addAll(criteria);
        this.mapColumns = List.copyOf(map);
        List<String> all = new ArrayList<>(mapColumns);
        all.addAll(List.of(FAULT, "outcome", "ticks"));
        for (AccidentType t : AccidentType.values()) {
            all.add(t.column());
        }
        all.addAll(FAULT_ONLY);
        List<String> margins = marginColumns();
        all.addAll(margins);
        if (reasons) {
            all.add(CONTROLLER_FAILURE);
            all.add(CLAMPED_TICKS);
        }
        // a folder of another controller written before clamped ticks were counted lacks them: read as 0
        java.util.Set<String> optional = new java.util.HashSet<>(margins);
        optional.add(CLAMPED_TICKS);
        this.columns = new Columns(all, optional);
    }

    /** The near-miss and robustness columns, last: a folder written before they were kept lacks them and reads them unknown. */
    private static List<String> marginColumns() {
        List<String> names = new ArrayList<>();
        for (NearMiss m : NearMiss.values()) {
            names.add(m.column());
        }
        for (AccidentType t : AccidentType.values()) {
            names.add(t.robustnessColumn());
        }
        return names;
    }

    public Columns columns() {
        return columns;
    }

    public String header() {
        return columns.header();
    }

    /** The block of rows of one map, each ending in '\n'. */
    String block(MapRun run) {
        StringBuilder out = new StringBuilder();
        Columns.Row faultFree = mapRow(run).set(FAULT, NO_FAULT);
        result(faultFree, run.faultFree());
        FAULT_ONLY.forEach(c -> faultFree.set(c, ""));
        out.append(faultFree.line());
        for (FaultOutcome f : run.faults()) {
            Columns.Row row = mapRow(run).set(FAULT, f.variant().id());
            result(row, f.run());
            row.set(REACHED, f.reached()).set(EFFECTIVE, f.effective()).set(FIRST_EFFECTIVE_TICK, f.firstEffectiveTick())
                    .set(DETECTION, f.detection()).set(NEW_ACCIDENT, f.newAccident().map(Enum::name).orElse(""))
                    .set(PAPER_FOUND, f.paperFound());
            out.append(row.line());
        }
        return out.toString();
    }

    private Columns.Row mapRow(MapRun run) {
        Columns.Row row = columns.row().set("replication", run.replication()).set("driver", run.driver())
                .set("map_index", run.mapIndex()).set("candidate", run.candidate()).set("map", run.map().text())
                .set("external_seed", run.externalSeed()).set("internal_seed", run.internalSeed()).set("cell", run.cell());
        for (int c = 0; c < criteria.size(); c++) {
            row.set(criteria.get(c), String.format(Locale.ROOT, "%.3f", run.criteria().get(c)));
        }
        return row;
    }

    private void result(Columns.Row row, RunSummary r) {
        row.set("outcome", r.outcome()).set("ticks", r.ticks());
        if (reasons) {
            row.set(CONTROLLER_FAILURE, reason(r.failureReason())).set(CLAMPED_TICKS, r.clampedTicks());
        }
        for (AccidentType t : AccidentType.values()) {
            row.set(t.column(), r.accidents().get(t.ordinal()));
        }
        Margins m = r.margins();
        for (NearMiss n : NearMiss.values()) {
            row.set(n.column(), margin(m.least(n)));
        }
        for (AccidentType t : AccidentType.values()) {
            row.set(t.robustnessColumn(), margin(m.robustness(t)));
        }
    }

    /** A controller's reason in one cell: its first line, no commas or quotes, at most {@link #REASON_CHARS} characters. */
    static String reason(String text) {
        String line = text.lines().findFirst().orElse("").replace(',', ';').replace('"', '\'').strip();
        return line.length() <= REASON_CHARS ? line : line.substring(0, REASON_CHARS - 1) + "…";
    }

    /** A margin as runs.csv writes it: {@link Margins#DECIMALS} decimals, "inf" never met, blank unknown. */
    static String margin(double v) {
        if (Double.isNaN(v)) {
            return "";
        }
        if (Double.isInfinite(v)) {
            return v > 0 ? "inf" : "-inf";
        }
        return String.format(Locale.ROOT, "%." + Margins.DECIMALS + "f", v);
    }

    static double margin(String text) {
        return switch (text) {
            case "" -> Double.NaN;
            case "inf" -> Double.POSITIVE_INFINITY;
            case "-inf" -> Double.NEGATIVE_INFINITY;
            default -> Margins.kept(Double.parseDouble(text));
        };
    }

    /**
     * The complete map blocks of a runs.csv text, in file order. A block cut short (a kill while it
     * was written) ends the reading; anything else malformed is refused, naming the line.
     */
    List<MapRun> read(String text, String source) {
        return read(CsvLines.complete(text), source, "run the experiment again into a new folder");
    }

    /**
     * The complete map blocks of runs.csv's whole lines (see {@link CsvLines}), read by the names of
     * the file's header.
     *
     * @param fix what the user can do about a header that does not fit this experiment
     */
    List<MapRun> read(List<String> lines, String source, String fix) {
        if (lines.isEmpty()) {
            throw new IllegalArgumentException(source + ": expected the header of this experiment's runs.csv:\n  "
                    + header() + "\nfound nothing; " + fix);
        }
        Columns.Layout layout = columns.layout(lines.get(0), source, fix);
        List<MapRun> runs = new ArrayList<>();
        int i = 1;
        while (i + faults.size() < lines.size()) {
            int line = i + 1;
            try {
                Columns.Line first = layout.split(lines.get(i));
                check(first.get(FAULT).equals(NO_FAULT), "a fault-free row (fault " + NO_FAULT + ")");
                List<Double> values = new ArrayList<>();
                for (String c : criteria) {
                    values.add(first.decimal(c));
                }
                RunSummary faultFree = summary(first);
                List<FaultOutcome> outcomes = new ArrayList<>();
                for (int f = 0; f < faults.size(); f++) {
                    line = i + 2 + f;
                    Columns.Line row = layout.split(lines.get(i + 1 + f));
                    check(mapColumns.stream().allMatch(c -> row.get(c).equals(first.get(c))),
                            "a row of the same map as line " + (i + 1));
                    check(row.get(FAULT).equals(Integer.toString(faults.get(f).id())), "fault " + faults.get(f).id());
                    String accident = row.get(NEW_ACCIDENT);
                    outcomes.add(new FaultOutcome(faults.get(f), summary(row), row.bool(REACHED), row.bool(EFFECTIVE),
                            row.longValue(FIRST_EFFECTIVE_TICK), Detection.valueOf(row.get(DETECTION)),
                            accident.isEmpty() ? Optional.empty() : Optional.of(Failure.valueOf(accident)),
                            row.bool(PAPER_FOUND)));
                }
                runs.add(new MapRun(first.integer("replication"), first.get("driver"), first.integer("map_index"),
                        first.integer("candidate"), MapId.parse(first.get("map")), first.longValue("external_seed"),
                        first.longValue("internal_seed"), first.integer("cell"), values, faultFree, outcomes));
            } catch (IllegalArgumentException e) {
                throw new IllegalArgumentException(source + ":" + line + ": " + e.getMessage());
            }
            i += 1 + faults.size();
        }
        return runs;
    }

    private RunSummary summary(Columns.Line row) {
        List<Long> counts = new ArrayList<>();
        for (AccidentType t : AccidentType.values()) {
            counts.add(row.longValue(t.column()));
        }
        List<Double> near = new ArrayList<>();
        for (NearMiss n : NearMiss.values()) {
            near.add(margin(row.get(n.column())));
        }
        List<Double> rho = new ArrayList<>();
        for (AccidentType t : AccidentType.values()) {
            rho.add(margin(row.get(t.robustnessColumn())));
        }
        return new RunSummary(Outcome.valueOf(row.get("outcome")), row.longValue("ticks"), counts, new Margins(near, rho),
                reasons ? row.get(CONTROLLER_FAILURE) : "", reasons && !row.get(CLAMPED_TICKS).isEmpty() ? row.longValue(CLAMPED_TICKS) : 0);
    }

    private static void check(boolean ok, String expected) {
        if (!ok) {
            throw new IllegalArgumentException("expected " + expected);
        }
    }
}
