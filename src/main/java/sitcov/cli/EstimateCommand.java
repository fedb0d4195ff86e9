package sitcov.cli;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import sitcov.control.ControllerFactory;
import sitcov.estimate.EstimateConfig;
import sitcov.estimate.EstimateFolder;
import sitcov.estimate.EstimateReport;
import sitcov.estimate.EstimateRunner;
import sitcov.estimate.ProposalRow;
import sitcov.estimate.ProposalTable;
import sitcov.estimate.Sample;
import sitcov.estimate.SampleTable;
import sitcov.experiment.Shard;
import sitcov.judge.RunObserver;
import sitcov.judge.Simulator;
import sitcov.protocol.ControllerChoice;
import sitcov.protocol.ControllerStartException;
import sitcov.protocol.ExecControllers;
import sitcov.results.IoReason;

/**
 * {@code estimate PRESET}: how often the controller fails on the generator's maps, by plain Monte
 * Carlo and by importance sampling under a cross-entropy proposal (experiments/estimate.md), into a
 * results folder; {@code --shard K/N} runs replications K-1, K-1+N, …, and {@code merge} joins the shards.
 */
final class EstimateCommand implements Command {
    @Override
    public String name() {
        return "estimate";
    }

    @Override
    public String synopsis() {
        return "PRESET [--out DIR (default: target/results/PRESET-seedS)] [--seed MASTER] [--replications N]"
                + " [--controller builtin|builtin:FAULTS|exec:COMMAND] [--threads T] [--shard K/N] [--dry-run]";
    }

    @Override
    public String summary() {
        return "estimate the controller's failure rate on the generator's maps: plain Monte Carlo and importance sampling";
    }

    @Override
    public int run(List<String> args, PrintStream out, PrintStream err) throws UsageException {
        Options options = Options.parse(name(), args, Set.of("--out", "--seed", "--replications", "--controller",
                "--threads", "--shard"), Set.of("--dry-run"));
        if (options.positional().size() != 1) {
            throw new UsageException("estimate: name one preset with protocol=estimate, e.g. 'estimate estimate-rq1'.");
        }
        Path file = Preset.locate(options.positional().get(0));
        if (!EstimatePreset.isEstimate(file)) {
            throw new UsageException("estimate: " + file + " is not an estimate's preset (it lacks protocol=estimate);"
                    + " run it with 'run', or name an estimate's preset such as estimate-rq1.");
        }
        return start(file, options, out, err);
    }

    /** Runs the estimate preset {@code file} as {@code options} say; {@code run PRESET} comes here for an estimate. */
    static int start(Path file, Options options, PrintStream out, PrintStream err) throws UsageException {
        int threads = options.threads(err);
        EstimateConfig config = EstimatePreset.read(file, options.seed("--seed").orElse(null),
                options.count("--replications", 1, EstimateConfig.MAX_REPLICATIONS).orElse(null),
                options.value("--controller").orElse(null));
        ControllerChoice choice;
        try {
            choice = ControllerChoice.parse(config.controller());
        } catch (IllegalArgumentException e) {
            throw new UsageException("estimate: controller: " + e.getMessage() + ".");
        }
        Shard shard = shard(options, config);
        String plan = "estimate: " + config.name() + (shard.isWhole() ? "" : " shard " + shard) + ": " + config.controller()
                + ", " + config.replications() + " replication" + (config.replications() == 1 ? "" : "s") + " of "
                + config.mcMaps() + " plain Monte Carlo maps and " + config.ceStages() + " x " + config.ceMaps()
                + " cross-entropy + " + config.isMaps() + " importance-sampling maps, on " + threads + " threads";
        if (options.has("--dry-run")) {
            out.println(plan + ": sound; a dry run, so nothing ran and nothing was written.");
            return ExitCode.OK;
        }
        Path folder = folder(options, config, shard);
        try (ControllerChoice.Workers workers = choice.open(Version.current(), ExecControllers.DEFAULT_TICK_TIMEOUT_MILLIS,
                ExecControllers.DEFAULT_HANDSHAKE_TIMEOUT_MILLIS)) {
            try {
                workers.check(null);
            } catch (ControllerStartException e) {
                throw new UsageException("estimate: " + e.getMessage() + "; fix the controller the preset or --controller names.");
            }
            err.println(plan);
            List<String> samples = new ArrayList<>();
            List<String> proposals = new ArrayList<>();
            try (EstimateRunner runner = new EstimateRunner(config, () -> {
                ControllerFactory factory = workers.worker(null);
                return (map, seed) -> Simulator.run(map, seed, Set.of(), RunObserver.NONE, factory).result();
            }, threads, line -> err.println("estimate: " + line))) {
                for (int r = 0; r < config.replications(); r++) {
                    if (shard.includes(r)) {
                        EstimateRunner.Replication done = runner.run(r);
                        done.samples().stream().map(SampleTable::row).forEach(samples::add);
                        done.proposals().stream().map(ProposalTable::row).forEach(proposals::add);
                    }
                }
            }
            EstimateReport report = EstimateFolder.write(folder, config, Version.current(), shard.k(), shard.n(),
                    samples, proposals, true);
            report.text().forEach(out::println);
            out.println();
            out.println("Results in " + folder);
            return ExitCode.OK;
        } catch (IOException e) {
            err.println("sitcov: estimate: could not write " + folder + ": " + IoReason.of(e, folder) + ".");
            return ExitCode.FAILURE;
        }
    }

    private static Shard shard(Options options, EstimateConfig config) throws UsageException {
        if (options.value("--shard").isEmpty()) {
            return Shard.WHOLE;
        }
        Shard shard;
        try {
            shard = Shard.parse(options.value("--shard").get());
        } catch (IllegalArgumentException e) {
            throw new UsageException("estimate: --shard: " + e.getMessage() + ".");
        }
        if (shard.n() > config.replications()) {
            throw new UsageException("estimate: --shard " + shard + ": " + config.name() + " has " + config.replications()
                    + " replications, so no more than " + config.replications() + " shards (each needs one); use --shard K/"
                    + config.replications() + ", or run more with --replications N.");
        }
        return shard;
    }

    private static Path folder(Options options, EstimateConfig config, Shard shard) throws UsageException {
        Path out = Path.of(options.value("--out").orElse(Path.of("target", "results", config.name() + "-seed"
                + config.masterSeed() + (shard.isWhole() ? "" : "-shard" + shard.k() + "of" + shard.n())).toString()));
        if (Files.isRegularFile(out) || (Files.isDirectory(out) && !RunCommand.isEmpty(out))) {
            throw new UsageException("estimate: " + Options.shown(out) + " exists and is not an empty folder; results never"
                    + " overwrite earlier ones: name a new folder with --out.");
        }
        return out;
    }
}
