package sitcov.cli;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.stream.Stream;
import sitcov.experiment.Experiment;
import sitcov.experiment.ExperimentConfig;
import sitcov.experiment.MapRun;
import sitcov.experiment.Method;
import sitcov.experiment.Metrics;
import sitcov.experiment.ReplicationResult;
import sitcov.experiment.Sweep;
import sitcov.report.ExperimentFigures;
import sitcov.report.ResultsWriter;
import sitcov.report.SweepReport;

/** {@code run PRESET}: the comparison experiment of a preset, into a fresh results folder. */
final class RunCommand implements Command {
    @Override
    public String name() {
        return "run";
    }

    @Override
    public String synopsis() {
        return "PRESET [--out DIR (default: target/results/PRESET-seedS)] [--seed MASTER] [--threads T]";
    }

    @Override
    public String summary() {
        return "run an experiment preset from experiments/ (smoke, paper-rq1, ...) and write its results folder";
    }

    @Override
    public int run(List<String> args, PrintStream out, PrintStream err) throws UsageException {
        Options options = Options.parse(name(), args, Set.of("--out", "--seed", "--threads"), Set.of());
        if (options.positional().size() != 1) {
            throw new UsageException("run: name one preset, e.g. 'run smoke' or 'run experiments/paper-rq1.properties'.");
        }
        Preset preset = Preset.read(Preset.locate(options.positional().get(0)), options.seed("--seed").orElse(null));
        Path presetFile = preset.file();
        ExperimentConfig config = preset.config();
        int threads = options.count("--threads", 1).orElse(Runtime.getRuntime().availableProcessors());
        Path folder = folder(options, config);
        List<Integer> sweep = preset.sweep();
        if (!sweep.isEmpty()) {
            return sweep(config, sweep, threads, folder, presetFile, out, err);
        }
        Progress progress = new Progress(err, "run " + config.name() + " (replications)",
                config.replications(), err == System.err && System.console() != null, System::nanoTime);
        err.println("run: " + config.name() + ": " + config.replications() + " replications of " + config.candidates()
                + " candidates, budget " + config.budget().key() + ", on " + threads + " threads ...");
        long start = System.nanoTime();
        List<ReplicationResult> results = Experiment.run(config, threads, System::nanoTime, progress::done);
        double seconds = (System.nanoTime() - start) / 1e9;
        Map<String, String> extras = new LinkedHashMap<>();
        extras.put("threads", Integer.toString(threads));
        extras.put("wall_seconds", String.format(Locale.ROOT, "%.1f", seconds));
        extras.put("preset_file", presetFile.toString());
        try {
            Files.createDirectories(folder);
            new ResultsWriter(config, results).writeAll(folder, extras);
            ExperimentFigures.writeAll(config, results, folder);
        } catch (IOException e) {
            err.println("sitcov: run: could not write the results into " + folder + ": " + e.getMessage());
            return ExitCode.FAILURE;
        }
        printTable(out, config, results);
        out.printf(Locale.ROOT, "Results in %s (%.1f s on %d threads)%n", folder, seconds, threads);
        return ExitCode.OK;
    }

    private static int sweep(ExperimentConfig config, List<Integer> budgets, int threads, Path folder, Path presetFile,
                             PrintStream out, PrintStream err) {
        int sets = budgets.size() * config.replications();
        err.println("run: " + config.name() + ": effort sweep over " + budgets + " candidates, " + config.replications()
                + " map sets each, on " + threads + " threads ...");
        Progress progress = new Progress(err, "run " + config.name() + " (map sets)", sets,
                err == System.err && System.console() != null, System::nanoTime);
        long start = System.nanoTime();
        List<Sweep.Point> points = Sweep.run(config, budgets, threads, System::nanoTime, progress::done);
        double seconds = (System.nanoTime() - start) / 1e9;
        try {
            Files.createDirectories(folder);
            SweepReport.write(config, points, folder, Map.of("threads", Integer.toString(threads),
                    "wall_seconds", String.format(Locale.ROOT, "%.1f", seconds), "preset_file", presetFile.toString(),
                    "sweep", budgets.toString().replaceAll("[\\[\\] ]", "")));
        } catch (IOException e) {
            err.println("sitcov: run: could not write the results into " + folder + ": " + e.getMessage());
            return ExitCode.FAILURE;
        }
        double[] fit = Sweep.regression(points.stream().mapToDouble(Sweep.Point::cells).toArray(),
                points.stream().mapToDouble(Sweep.Point::avgMapFault).toArray());
        out.printf(Locale.ROOT, "%s: %d map sets; avg-map-fault = %.3f + %.4f x cells covered, r^2 = %.3f%n",
                config.name(), points.size(), fit[0], fit[1], fit[2]);
        out.printf(Locale.ROOT, "Results in %s (%.1f s on %d threads)%n", folder, seconds, threads);
        return ExitCode.OK;
    }

    private static Path folder(Options options, ExperimentConfig config) throws UsageException {
        if (options.value("--out").isPresent()) {
            Path out = Path.of(options.value("--out").get());
            if (Files.isRegularFile(out) || (Files.isDirectory(out) && !isEmpty(out))) {
                throw new UsageException("run: --out " + out + " exists and is not an empty folder; results never"
                        + " overwrite earlier ones: name a new folder.");
            }
            return out;
        }
        Path base = Path.of("target", "results", config.name() + "-seed" + config.masterSeed());
        Path folder = base;
        for (int n = 2; Files.exists(folder); n++) {
            folder = Path.of(base + "-" + n);
        }
        return folder;
    }

    private static boolean isEmpty(Path dir) throws UsageException {
        try (Stream<Path> s = Files.list(dir)) {
            return s.findAny().isEmpty();
        } catch (IOException e) {
            throw new UsageException("run: cannot read the folder " + dir + ": " + e.getMessage());
        }
    }

    private static void printTable(PrintStream out, ExperimentConfig config, List<ReplicationResult> results) {
        var faults = config.faults().stream().sorted().toList();
        out.printf(Locale.ROOT, "%s: master seed %d, %d replications, %d candidates, budget %s; means over replications%n",
                config.name(), config.masterSeed(), config.replications(), config.candidates(), config.budget().key());
        out.printf(Locale.ROOT, "  %-9s %-13s %8s %8s %18s %19s %14s%n", "method", "notion", "maps", "cells",
                "method-prop-fault", "prop-map-all-fault", "avg-map-fault");
        for (Method m : Method.values()) {
            for (boolean paper : new boolean[] {false, true}) {
                double maps = 0;
                double cells = 0;
                double prop = 0;
                double all = 0;
                double avg = 0;
                for (ReplicationResult r : results) {
                    List<MapRun> runs = r.runsOf(m);
                    Metrics x = Metrics.of(runs, faults, paper);
                    maps += x.maps();
                    cells += x.cells();
                    prop += x.methodPropFault();
                    all += x.propMapAllFault();
                    avg += x.avgMapFault();
                }
                int n = results.size();
                out.printf(Locale.ROOT, "  %-9s %-13s %8.1f %8.1f %18.3f %19.3f %14.2f%n", m.key(),
                        paper ? "paper" : "differential", maps / n, cells / n, prop / n, all / n, avg / n);
            }
        }
    }
}
