package sitcov.results;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import sitcov.experiment.ExperimentConfig;
import sitcov.experiment.MapId;
import sitcov.experiment.MapRun;
import sitcov.faults.Fault;
import sitcov.judge.Detection;
import sitcov.judge.FaultOutcome;
import sitcov.judge.RunSummary;
import sitcov.oracle.AccidentType;
import sitcov.oracle.Outcome;

/**
 * {@code runs.csv}: one row per simulated run, a block per judged map (its fault-free row, then one
 * row per fault in id order). Nothing timed is in it. Reading it back gives the same maps, so a
 * resumed or merged experiment is computed from exactly what an uninterrupted one writes.
 */
public final class RunsCsv {
    private final ExperimentConfig config;
    private final List<Fault> faults;
    private final String header;

    public RunsCsv(ExperimentConfig config) {
        this.config = config;
        this.faults = config.faultList();
        StringBuilder h = new StringBuilder("replication,driver,map_index,candidate,map,external_seed,internal_seed,cell");
        for (var c : config.grid().criteria()) {
            h.append(',').append(c.key().replace('-', '_'));
        }
        h.append(",fault,outcome,ticks");
        for (AccidentType t : AccidentType.values()) {
            h.append(',').append(t.name().toLowerCase(Locale.ROOT));
        }
        h.append(",reached,effective,first_effective_tick,detection,new_accident,paper_found");
        this.header = h.toString();
    }

    public String header() {
        return header;
    }

    /** The block of rows of one map, each ending in '\n'. */
    String block(MapRun run) {
        StringBuilder prefix = new StringBuilder().append(run.replication()).append(',').append(run.driver()).append(',')
                .append(run.mapIndex()).append(',').append(run.candidate()).append(',').append(run.map().text()).append(',')
                .append(run.externalSeed()).append(',').append(run.internalSeed()).append(',').append(run.cell());
        for (double v : run.criteria()) {
            prefix.append(',').append(String.format(Locale.ROOT, "%.3f", v));
        }
        StringBuilder out = new StringBuilder();
        out.append(prefix).append(",NONE,").append(result(run.faultFree())).append(",,,,,,\n");
        for (FaultOutcome f : run.faults()) {
            out.append(prefix).append(',').append(f.fault().id()).append(',').append(result(f.run())).append(',')
                    .append(f.reached()).append(',').append(f.effective()).append(',').append(f.firstEffectiveTick())
                    .append(',').append(f.detection()).append(',').append(f.newAccident().map(Enum::name).orElse(""))
                    .append(',').append(f.paperFound()).append('\n');
        }
        return out.toString();
    }

    private static String result(RunSummary r) {
        StringBuilder s = new StringBuilder().append(r.outcome()).append(',').append(r.ticks());
        for (long n : r.accidents()) {
            s.append(',').append(n);
        }
        return s.toString();
    }

    /**
     * The complete map blocks of a runs.csv text, in file order. A block cut short (a kill while it
     * was written) ends the reading; anything else malformed is refused, naming the line.
     */
    List<MapRun> read(String text, String source) {
        return read(CsvLines.complete(text), source);
    }

    /** The complete map blocks of runs.csv's whole lines (see {@link CsvLines}). */
    List<MapRun> read(List<String> lines, String source) {
        if (lines.isEmpty() || !lines.get(0).equals(header)) {
            throw new IllegalArgumentException(source + ": expected the header of this experiment's runs.csv:\n  " + header
                    + "\nfound:\n  " + (lines.isEmpty() ? "(nothing)" : lines.get(0)));
        }
        int criteria = config.grid().criteria().size();
        int columns = header.split(",", -1).length;
        List<MapRun> runs = new ArrayList<>();
        int i = 1;
        while (i + faults.size() < lines.size()) {
            String[] first = lines.get(i).split(",", -1);
            int line = i + 1;
            try {
                check(first.length == columns && first[8 + criteria].equals("NONE"), "a fault-free row (fault NONE)");
                List<Double> values = new ArrayList<>();
                for (int c = 0; c < criteria; c++) {
                    values.add(Double.parseDouble(first[8 + c]));
                }
                RunSummary faultFree = summary(first, 9 + criteria);
                List<FaultOutcome> outcomes = new ArrayList<>();
                for (int f = 0; f < faults.size(); f++) {
                    line = i + 2 + f;
                    String[] row = lines.get(i + 1 + f).split(",", -1);
                    check(row.length == columns && String.join(",", java.util.Arrays.copyOf(row, 8 + criteria))
                            .equals(String.join(",", java.util.Arrays.copyOf(first, 8 + criteria))),
                            "a row of the same map as line " + (i + 1));
                    check(row[8 + criteria].equals(Integer.toString(faults.get(f).id())), "fault " + faults.get(f).id());
                    int at = 10 + criteria + AccidentType.values().length;
                    outcomes.add(new FaultOutcome(faults.get(f), summary(row, 9 + criteria), bool(row[at + 1]),
                            bool(row[at + 2]), Long.parseLong(row[at + 3]), Detection.valueOf(row[at + 4]),
                            row[at + 5].isEmpty() ? Optional.empty() : Optional.of(AccidentType.valueOf(row[at + 5])),
                            bool(row[at + 6])));
                }
                runs.add(new MapRun(Integer.parseInt(first[0]), first[1], Integer.parseInt(first[2]),
                        Integer.parseInt(first[3]), MapId.parse(first[4]), Long.parseLong(first[5]), Long.parseLong(first[6]),
                        Integer.parseInt(first[7]), values, faultFree, outcomes));
            } catch (IllegalArgumentException e) {
                throw new IllegalArgumentException(source + ":" + line + ": " + e.getMessage());
            }
            i += 1 + faults.size();
        }
        return runs;
    }

    private static RunSummary summary(String[] row, int at) {
        List<Long> counts = new ArrayList<>();
        for (int t = 0; t < AccidentType.values().length; t++) {
            counts.add(Long.parseLong(row[at + 2 + t]));
        }
        return new RunSummary(Outcome.valueOf(row[at]), Long.parseLong(row[at + 1]), counts);
    }

    private static boolean bool(String s) {
        return switch (s) {
            case "true" -> true;
            case "false" -> false;
            default -> throw new IllegalArgumentException("expected true or false, found '" + s + "'");
        };
    }

    private static void check(boolean ok, String expected) {
        if (!ok) {
            throw new IllegalArgumentException("expected " + expected);
        }
    }
}
