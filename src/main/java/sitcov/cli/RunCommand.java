package sitcov.cli;

import java.io.IOException;
import java.io.PrintStream;
import java.io.UncheckedIOException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.stream.Stream;
import sitcov.analysis.ControllerFailures;
import sitcov.builtin.BuiltinCar;
import sitcov.control.ControllerSource;
import sitcov.drivers.Drivers;
import sitcov.experiment.CampaignConfig;
import sitcov.experiment.ExperimentConfig;
import sitcov.experiment.ExperimentRunner;
import sitcov.experiment.Journal;
import sitcov.experiment.Shard;
import sitcov.report.ResultsRecorder;
import sitcov.results.CampaignManifest;
import sitcov.results.FolderLock;
import sitcov.results.IoReason;
import sitcov.results.Manifest;
import sitcov.results.ResultsFolder;

/**
 * {@code run PRESET}: an experiment into a fresh results folder, streamed as it goes;
 * {@code run --resume DIR} finishes one a kill interrupted; {@code --shard K/N} runs a share of it.
 */
final class RunCommand implements Command {
    private final Drivers drivers;
    /** This invocation's --fork: set first thing in {@link #run}. */
    private boolean fork = true;

    RunCommand(Drivers drivers) {
        this.drivers = drivers;
    }

    /** This command with checkpoints on or off ({@code --fork}), for a command that runs through {@link #start}. */
    RunCommand forking(boolean on) {
        fork = on;
        return this;
    }

    @Override
    public String name() {
        return "run";
    }

    @Override
    public String synopsis() {
        return "PRESET [--out DIR (default: target/results/PRESET-seedS)] [--seed MASTER] [--replications N] [--threads T] [--fork on|off]"
                + " [--shard K/N] [--record failures|all] [--dry-run]\n"
                + "       " + Main.LAUNCHER + " run --resume DIR [--threads T] [--fork on|off]\n"
                + "       " + Main.LAUNCHER + " run --again DIR [--out NEW] [--threads T] [--fork on|off] [--record failures|all] [--dry-run]";
    }

    @Override
    public String summary() {
        return "run an experiment preset (smoke, paper-rq1, ...) into a results folder; resume a killed run; run a folder's"
                + " experiment again; run a shard";
    }

    @Override
    public int run(List<String> args, PrintStream out, PrintStream err) throws UsageException {
        Options options = Options.parse(name(), args, Set.of("--out", "--seed", "--replications", "--threads", "--fork", "--shard",
                "--resume", "--again", "--controller", "--variants", "--record"), Set.of("--dry-run"));
        int threads = options.threads(err);
        fork = options.forks();
        if (options.value("--resume").isPresent()) {
            if (options.has("--dry-run")) {
                throw new UsageException("run: --dry-run checks a preset before it runs; it does not go with --resume.");
            }
            return resume(options, threads, out, err);
        }
        if (options.value("--again").isPresent()) {
            return RunAgain.run(this, options, threads, out, err);
        }
        if (options.positional().size() != 1) {
            throw new UsageException("run: name one preset, e.g. 'run smoke' or 'run experiments/paper-rq1.properties',"
                    + " or resume a folder with 'run --resume DIR'.");
        }
        Path presetFile = Preset.locate(options.positional().get(0));
        if (EstimatePreset.isEstimate(presetFile)) {
            if (options.has("--variants") || options.has("--fork") || options.has("--record")) {
                throw new UsageException("run: " + presetFile + " is an estimate (protocol=estimate), which takes neither"
                        + " --variants, --fork nor --record: drop them.");
            }
            return EstimateCommand.start(presetFile, options, out, err);
        }
        Map<String, String> keys = new java.util.HashMap<>();
        options.value("--controller").ifPresent(c -> keys.put("controller", c));
        options.value("--variants").ifPresent(v -> keys.put("variants", v));
        Preset preset = Preset.read(Preset.locate(options.positional().get(0)), options.seed("--seed").orElse(null),
                options.count("--replications", 1, ExperimentConfig.MAX_REPLICATIONS).orElse(null), keys, drivers);
        if (preset.campaign() != null) {
            return campaign(preset.campaign(), options, threads, out, err);
        }
        return start(preset.config(), options, preset.file().toString(), threads, out, err);
    }

    /**
     * Runs {@code config} into the folder {@code options} name (--out, --shard, --dry-run): a preset's
     * experiment, or one another command built ({@code versions}); {@code source} is kept in the
     * folder's execution record.
     */
    int start(ExperimentConfig config, Options options, String source, int threads, PrintStream out, PrintStream err)
            throws UsageException {
        return start(config, shard(options, config), options, source, threads, out, err);
    }

    int start(ExperimentConfig config, Shard shard, Options options, String source, int threads, PrintStream out,
                      PrintStream err) throws UsageException {
        boolean recordAll = options.recordsAll();
        if (options.has("--dry-run")) {
            if (options.has("--out")) {
                folder(options, config, shard);
            }
            ExperimentRunner runner = new ExperimentRunner(config, drivers, shard, Journal.empty(), threads, System::nanoTime,
                    List.of(), BuiltinCar.SOURCE);
            out.println(plan(runner, config, shard, threads) + ": sound; a dry run, so nothing ran and nothing was written.");
            return ExitCode.OK;
        }
        Path folder = folder(options, config, shard);
        Manifest manifest = new Manifest(config, Version.current(), shard, false, false).recordingAll(recordAll);
        // a controller program that cannot start is refused before a results folder is made for it
        Controllers.Opened controllers = Controllers.open(config, folder);
        Map<String, String> execution = execution(threads);
        execution.put("preset_file", source);
        ResultsRecorder recorder;
        try {
            recorder = create(folder, manifest, execution);
        } catch (UsageException e) {
            controllers.close();
            throw e;
        }
        return execute(recorder, controllers, folder, threads, "", out, err);
    }

    /**
     * A campaign (experiments/README.md, "Campaigns: falsifying one version"): each target into its own sub-folder; a
     * shard runs that share of every target's trials.
     */
    private int campaign(CampaignConfig c, Options options, int threads, PrintStream out, PrintStream err)
            throws UsageException {
        return campaign(c, shard(options, c.trials(), c.name(), "trials", true), options, threads, out, err);
    }

    int campaign(CampaignConfig c, Shard shard, Options options, int threads, PrintStream out, PrintStream err)
            throws UsageException {
        if (options.has("--record")) {
            throw new UsageException("run: " + c.name() + " is a campaign, whose trials keep the recordings of"
                    + " their failures only; --record all is for test suites (run, versions): drop --record.");
        }
        if (options.has("--dry-run")) {
            out.println(CampaignRun.plan(c, shard, threads) + ": sound; a dry run, so nothing ran and nothing was written.");
            return ExitCode.OK;
        }
        Path folder = folder(options, c.name(), c.masterSeed(), c.trials(), shard);
        return new CampaignRun(drivers, threads, fork, out, err).start(c, shard, folder);
    }

    private static ResultsRecorder create(Path folder, Manifest manifest, Map<String, String> execution)
            throws UsageException {
        try {
            return ResultsRecorder.create(folder, manifest, execution, System::nanoTime, BuiltinCar.FACTORY);
        } catch (IOException e) {
            throw new UsageException("run: cannot create the results folder " + folder + ": " + IoReason.of(e, folder)
                    + "; choose a writable --out.");
        } catch (IllegalStateException e) {
            throw new UsageException("run: " + e.getMessage() + ".");
        } catch (IllegalArgumentException e) {
            throw new UsageException("run: " + e.getMessage() + "; name a new folder with --out.");
        }
    }

    private int resume(Options options, int threads, PrintStream out, PrintStream err) throws UsageException {
        if (!options.positional().isEmpty() || options.has("--out") || options.has("--seed") || options.has("--shard")
                || options.has("--replications")) {
            throw new UsageException("run: --resume DIR takes everything from DIR's manifest; give only --threads and --fork beside it.");
        }
        if (options.has("--record")) {
            throw new UsageException("run: --resume DIR records as the run it resumes did (its manifest says which runs);"
                    + " drop --record.");
        }
        Path folder = Path.of(options.value("--resume").get());
        if (folder.toString().isEmpty() || !Files.isDirectory(folder)) {
            throw new UsageException("run: --resume " + Options.shown(folder) + " is not a folder; name the results folder"
                    + " of the run to resume.");
        }
        if (sitcov.estimate.EstimateFolder.isEstimate(folder)) {
            throw new UsageException("run: " + folder + " holds an estimate, which is written whole at its end and does not"
                    + " resume; run its preset again into a new folder (the same seeds give the same results).");
        }
        if (CampaignManifest.isCampaign(folder)) {
            return new CampaignRun(drivers, threads, fork, out, err).resume(folder);
        }
        Manifest manifest;
        try {
            if (!Files.exists(folder.resolve(ResultsFolder.MANIFEST)) && Files.exists(folder.resolve(ResultsFolder.LOCK))
                    && ResultsFolder.holdsNothing(folder)) {
                throw new UsageException("run: " + folder + " holds no results: the run that made it was stopped before it"
                        + " wrote any; start it again with 'run PRESET --out " + folder + "'.");
            }
            manifest = Manifest.read(folder);
            if (manifest.complete()) {
                throw new UsageException("run: " + folder + " is complete already; there is nothing to resume.");
            }
            if (!manifest.version().equals(Version.current())) {
                throw new UsageException("run: " + folder + " was written by sitcov " + manifest.version() + ", this is "
                        + Version.current() + "; resume it with that version, or start the preset afresh.");
            }
            if (!manifest.checked()) {
                err.println("sitcov: run: " + Manifest.uncheckedWarning(folder) + ".");
            }
            Controllers.Opened controllers = Controllers.open(manifest.config(), folder);
            ResultsRecorder recorder;
            try {
                recorder = ResultsRecorder.resume(folder, manifest, execution(threads), System::nanoTime,
                        BuiltinCar.FACTORY);
            } catch (IOException | RuntimeException e) {
                controllers.close();
                throw e;
            }
            return execute(recorder, controllers, folder, threads, " (resumed with " + recorder.journal().size() + " maps judged before)",
                    out, err);
        } catch (IOException e) {
            throw new UsageException("run: cannot resume " + folder + ": " + IoReason.of(e, folder) + ".");
        } catch (IllegalArgumentException | IllegalStateException e) {
            throw new UsageException("run: cannot resume " + folder + ": " + e.getMessage() + ".");
        }
    }

    private int execute(ResultsRecorder recorder, Controllers.Opened opened, Path folder, int threads, String note,
                        PrintStream out, PrintStream err) {
        Controllers.Opened controllers = fork ? opened : opened.unforked();
        Manifest manifest = recorder.manifest();
        ExperimentConfig config = manifest.config();
        ProgressListener progress = new ProgressListener(err, err == System.err && System.console() != null,
                System::nanoTime);
        ExperimentRunner runner = new ExperimentRunner(config, drivers, manifest.shard(), recorder.journal(), threads,
                System::nanoTime, List.of(recorder, progress), controllers.reference(), controllers.variants())
                .recordingAll(manifest.recordsAll());
        err.println(plan(runner, config, manifest.shard(), threads) + ", into " + folder + note);
        try (controllers) {
            runner.run();
        } catch (FolderLock.Lost e) {
            err.println("sitcov: run: " + e.getMessage() + "; it stopped there, and what it had judged went with the"
                    + " folder: run the preset again.");
            return ExitCode.FAILURE;
        } catch (IllegalStateException | UncheckedIOException e) {
            err.println("sitcov: run: " + e.getMessage());
            err.println("sitcov: run: what was judged is kept in " + folder + "; continue with 'run --resume " + folder + "'.");
            return ExitCode.FAILURE;
        } finally {
            try {
                recorder.close();
            } catch (IOException e) {
                err.println("sitcov: run: could not close the journal in " + folder + ": " + IoReason.of(e) + ".");
            }
        }
        SummaryTable.print(out, config, recorder.summary());
        VerdictPrinter.print(out, folder);
        out.println("Results in " + folder + " (" + progress.elapsed() + " on " + threads + (threads == 1 ? " thread)" : " threads)"));
        Path report = folder.resolve(ResultsFolder.REPORT);
        if (Files.isRegularFile(report)) {
            out.println("The report: " + report + " (the verdict, every table and figure on one page; open it in a browser)");
        }
        if (ControllerFailures.of(recorder.summary().results(), config.variants()).referenceAlwaysFailed()) {
            err.println("sitcov: run: the reference controller " + config.controller() + " failed on every map (see the"
                    + " verdict and controller-N.log in " + folder + ").");
            return ExitCode.FAILURE;
        }
        return ExitCode.OK;
    }

    /** What a run does, as its first line says it: "run: smoke shard 1/2: 1 replications, drivers …, on 2 threads". */
    private static String plan(ExperimentRunner runner, ExperimentConfig config, Shard shard, int threads) {
        return "run: " + config.name() + (shard.isWhole() ? "" : " shard " + shard) + ": " + runner.replications().size()
                + (config.isSweep() ? " map sets" : " replications") + ", drivers " + String.join(", ", config.drivers())
                + ", budget " + config.budget().key() + ", on " + threads + " threads";
    }

    static Map<String, String> execution(int threads) {
        Map<String, String> m = new LinkedHashMap<>();
        m.put("threads", Integer.toString(threads));
        m.put("java_version", System.getProperty("java.version"));
        m.put("os", System.getProperty("os.name") + " " + System.getProperty("os.arch"));
        m.put("cores", Integer.toString(Runtime.getRuntime().availableProcessors()));
        return m;
    }

    /** The shard asked for; refused when it splits the replications into more shards than there are of them. */
    private static Shard shard(Options options, ExperimentConfig config) throws UsageException {
        return shard(options, config.planSize(), config.name(), config.isSweep() ? "map sets" : "replications",
                !config.isSweep());
    }

    /** The shard asked for of {@code units} {@code what}; refused when it asks for more shards than there are units. */
    private static Shard shard(Options options, int units, String name, String what, boolean more) throws UsageException {
        if (options.value("--shard").isEmpty()) {
            return Shard.WHOLE;
        }
        Shard shard;
        try {
            shard = Shard.parse(options.value("--shard").get());
        } catch (IllegalArgumentException e) {
            throw new UsageException("run: --shard: " + e.getMessage() + ".");
        }
        if (shard.n() > units) {
            throw new UsageException("run: --shard " + shard + ": " + name + " has " + units + " " + what + ", so no"
                    + " more than " + units + " shards (each needs one); use --shard K/" + units
                    + (more ? ", or run more with --replications N" : "") + ".");
        }
        return shard;
    }

    private static Path folder(Options options, ExperimentConfig config, Shard shard) throws UsageException {
        return folder(options, config.name(), config.masterSeed(), config.replications(), shard);
    }

    private static Path folder(Options options, String name, long masterSeed, int replications, Shard shard)
            throws UsageException {
        if (options.value("--out").isPresent()) {
            Path out = Path.of(options.value("--out").get());
            if (Files.isRegularFile(out) || (Files.isDirectory(out) && !holdsNothing(out))) {
                boolean results = Files.isRegularFile(out.resolve(ResultsFolder.MANIFEST));
                throw new UsageException("run: --out " + Options.shown(out) + " exists and is not an empty folder; results never"
                        + " overwrite earlier ones: name a new folder" + (results ? " (or resume it with run --resume " + out
                        + ")" : "") + ".");
            }
            return out;
        }
        Path base = Path.of("target", "results", name + "-seed" + masterSeed
                + (options.has("--replications") ? "-reps" + replications : "")
                + (shard.isWhole() ? "" : "-shard" + shard.k() + "of" + shard.n()));
        try {
            Files.createDirectories(base.getParent());
            // created here, atomically: of two runs racing for a name, one gets it and the other the next
            for (int n = 1;; n++) {
                Path folder = n == 1 ? base : Path.of(base + "-" + n);
                try {
                    return Files.createDirectory(folder);
                } catch (FileAlreadyExistsException e) {
                    // taken: try the next number
                }
            }
        } catch (IOException e) {
            throw new UsageException("run: cannot create a results folder under " + base.getParent() + ": "
                    + IoReason.of(e, base.getParent()) + "; run from a writable folder or name one with --out.");
        }
    }

    /** Empty, or holding only what a run stopped before it wrote anything left (its lock, temporary files). */
    private static boolean holdsNothing(Path dir) throws UsageException {
        try {
            return ResultsFolder.holdsNothing(dir);
        } catch (IOException e) {
            throw new UsageException("cannot read the folder " + dir + ": " + e.getMessage());
        }
    }

    static boolean isEmpty(Path dir) throws UsageException {
        try (Stream<Path> s = Files.list(dir)) {
            return s.findAny().isEmpty();
        } catch (IOException e) {
            throw new UsageException("cannot read the folder " + dir + ": " + IoReason.of(e, dir) + ".");
        }
    }
}
