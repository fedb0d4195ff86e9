package sitcov.report;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;
import sitcov.experiment.CurvePoint;
import sitcov.experiment.ExperimentConfig;
import sitcov.experiment.FaultVerdict;
import sitcov.experiment.MapRun;
import sitcov.experiment.Method;
import sitcov.experiment.Metrics;
import sitcov.experiment.ReplicationResult;
import sitcov.faults.Fault;
import sitcov.faults.FaultSet;
import sitcov.oracle.AccidentType;
import sitcov.oracle.RunResult;

/**
 * Writes an experiment's results folder: {@code runs.csv} (one row per simulated run, nothing
 * timed, reproducible byte for byte), {@code summary.csv} (the paper's measures per method and
 * replication under both detection notions), {@code coverage-curve.csv}, {@code timings.csv} and
 * {@code manifest.properties}. Each file is written whole and moved into place.
 */
public final class ResultsWriter {
    private final ExperimentConfig config;
    private final List<ReplicationResult> results;
    private final List<Fault> faults;

    public ResultsWriter(ExperimentConfig config, List<ReplicationResult> results) {
        this.config = config;
        this.results = results;
        this.faults = config.faults().stream().sorted().toList();
    }

    public void writeAll(Path folder, Map<String, String> manifestExtras) throws IOException {
        write(folder.resolve("runs.csv"), runs());
        write(folder.resolve("summary.csv"), summary());
        write(folder.resolve("table2.csv"), table2());
        write(folder.resolve("coverage-curve.csv"), curve());
        write(folder.resolve("timings.csv"), timings());
        write(folder.resolve("manifest.properties"), manifest(manifestExtras));
    }

    List<String> runs() {
        List<String> rows = new ArrayList<>();
        StringBuilder header = new StringBuilder("method,replication,candidate,external_seed,internal_seed,cell");
        for (var c : config.grid().criteria()) {
            header.append(',').append(c.key().replace('-', '_'));
        }
        header.append(",fault,outcome,ticks");
        for (AccidentType t : AccidentType.values()) {
            header.append(',').append(t.name().toLowerCase(Locale.ROOT));
        }
        header.append(",reached,effective,first_effective_tick,detection,new_accident,paper_found");
        rows.add(header.toString());
        for (ReplicationResult r : results) {
            for (MapRun run : r.runs()) {
                String prefix = run.method().key() + "," + run.replication() + "," + run.candidate() + ","
                        + run.externalSeed() + "," + run.internalSeed() + "," + run.cell() + criteria(run);
                rows.add(prefix + ",NONE," + result(run.faultFree()) + ",,,,,,");
                for (FaultVerdict v : run.verdicts()) {
                    rows.add(prefix + "," + v.fault().id() + "," + result(v.faultyRun()) + "," + v.activation().reached()
                            + "," + v.activation().effective() + "," + v.activation().firstEffectiveTick() + ","
                            + v.detection() + "," + v.newAccident().map(a -> a.type().name()).orElse("") + ","
                            + v.foundByPaperNotion());
                }
            }
        }
        return rows;
    }

    private static String criteria(MapRun run) {
        StringBuilder s = new StringBuilder();
        for (double v : run.criteria()) {
            s.append(',').append(String.format(Locale.ROOT, "%.3f", v));
        }
        return s.toString();
    }

    private static String result(RunResult r) {
        StringBuilder s = new StringBuilder(r.outcome() + "," + r.ticks());
        for (AccidentType t : AccidentType.values()) {
            s.append(',').append(r.count(t));
        }
        return s.toString();
    }

    List<String> summary() {
        List<String> rows = new ArrayList<>();
        StringBuilder header = new StringBuilder("method,replication,notion,maps_run,cells_covered,cells_total,"
                + "method_prop_fault,prop_map_all_fault,avg_map_fault");
        for (Fault f : faults) {
            header.append(",fault_").append(f.id());
        }
        rows.add(header.toString());
        for (ReplicationResult r : results) {
            for (Method m : Method.values()) {
                List<MapRun> runs = r.runsOf(m);
                for (String notion : List.of("differential", "paper")) {
                    Metrics x = Metrics.of(runs, faults, notion.equals("paper"));
                    StringBuilder s = new StringBuilder(String.format(Locale.ROOT, "%s,%d,%s,%d,%d,%d,%.4f,%.4f,%.4f",
                            m.key(), r.replication(), notion, x.maps(), x.cells(), config.grid().cells(), x.methodPropFault(),
                            x.propMapAllFault(), x.avgMapFault()));
                    for (double p : x.perFault()) {
                        s.append(String.format(Locale.ROOT, ",%.4f", p));
                    }
                    rows.add(s.toString());
                }
            }
        }
        return rows;
    }

    /** The paper's Table 2: per fault, the share of maps finding it by each method (mean over replications) and the difference. */
    List<String> table2() {
        List<String> rows = new ArrayList<>();
        rows.add("fault,name,notion,coverage,random,difference");
        for (String notion : List.of("differential", "paper")) {
            double[][] mean = new double[2][faults.size()];
            for (ReplicationResult r : results) {
                for (Method m : Method.values()) {
                    double[] p = Metrics.of(r.runsOf(m), faults, notion.equals("paper")).perFault();
                    for (int f = 0; f < p.length; f++) {
                        mean[m.ordinal()][f] += p[f] / results.size();
                    }
                }
            }
            for (int f = 0; f < faults.size(); f++) {
                double c = mean[Method.COVERAGE_FILTER.ordinal()][f];
                double q = mean[Method.RANDOM.ordinal()][f];
                rows.add(String.format(Locale.ROOT, "%d,%s,%s,%.4f,%.4f,%.4f", faults.get(f).id(), faults.get(f).label(),
                        notion, c, q, c - q));
            }
        }
        return rows;
    }

    private List<String> curve() {
        List<String> rows = new ArrayList<>();
        rows.add("method,replication,candidates,maps_run,ticks,cells_covered,seconds");
        for (ReplicationResult r : results) {
            for (CurvePoint p : r.curve()) {
                rows.add(String.format(Locale.ROOT, "%s,%d,%d,%d,%d,%d,%.3f", p.method().key(), p.replication(),
                        p.candidates(), p.mapsRun(), p.ticks(), p.cellsCovered(), p.seconds()));
            }
        }
        return rows;
    }

    private List<String> timings() {
        List<String> rows = new ArrayList<>();
        rows.add("method,replication,candidate,external_seed,seconds");
        for (ReplicationResult r : results) {
            for (int i = 0; i < r.runs().size(); i++) {
                MapRun run = r.runs().get(i);
                rows.add(String.format(Locale.ROOT, "%s,%d,%d,%d,%.4f", run.method().key(), run.replication(),
                        run.candidate(), run.externalSeed(), r.mapNanos().get(i) / 1e9));
            }
            rows.add(String.format(Locale.ROOT, "coverage-phase,%d,,,%.4f", r.replication(), r.coverageNanos() / 1e9));
            rows.add(String.format(Locale.ROOT, "random-phase,%d,,,%.4f", r.replication(), r.randomNanos() / 1e9));
        }
        return rows;
    }

    private List<String> manifest(Map<String, String> extras) {
        Map<String, String> m = new TreeMap<>();
        m.put("preset", config.name());
        m.put("master_seed", Long.toString(config.masterSeed()));
        m.put("candidates", Integer.toString(config.candidates()));
        m.put("replications", Integer.toString(config.replications()));
        m.put("faults", FaultSet.format(config.faults()));
        m.put("budget", config.budget().key());
        m.put("java_version", System.getProperty("java.version"));
        m.putAll(extras);
        List<String> rows = new ArrayList<>();
        rows.add("# sitcov experiment manifest");
        m.forEach((k, v) -> rows.add(k + "=" + v));
        return rows;
    }

    private static void write(Path file, List<String> rows) throws IOException {
        AtomicFiles.writeLines(file, rows);
    }
}
