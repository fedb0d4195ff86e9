package sitcov.cli;

import java.io.IOException;
import java.io.PrintStream;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.Set;
import java.util.stream.Collectors;
import sitcov.control.ControllerFactory;
import sitcov.faults.Activation;
import sitcov.faults.Fault;
import sitcov.judge.BatchedRuns;
import sitcov.judge.LiveRun;
import sitcov.judge.RunObserver;
import sitcov.judge.RunRecord;
import sitcov.judge.RunRecord;
import sitcov.judge.Simulator;
import sitcov.oracle.Accident;
import sitcov.oracle.AccidentType;
import sitcov.oracle.RunResult;
import sitcov.protocol.BatchingProxy;
import sitcov.protocol.ControllerChoice;
import sitcov.protocol.ControllerStartException;
import sitcov.protocol.ExecControllers;
import sitcov.recording.Recording;
import sitcov.recording.RecordingFile;
import sitcov.render.NearMissWatch;
import sitcov.render.RunGallery;
import sitcov.render.RunRenderer;
import sitcov.render.TraceWriter;
import sitcov.render.TrajectoryRecorder;
import sitcov.results.IoReason;
import sitcov.world.MapGenerator;
import sitcov.world.WorldMap;

/**
 * {@code simulate}: one fault-free run of a map (from a seed or a situation file), printed as one
 * line with both seeds, optionally drawn to PNG and traced to CSV; or, with {@code --maps N}, the
 * fault-free calibration over N maps in a row, one thread, deterministic.
 */
final class SimulateCommand implements Command {
    /** The calibration keeps every run's result for its summary. */
    static final int MAX_MAPS = 1_000_000;

    private static final int PIXELS_PER_METRE = 6;

    @Override
    public String name() {
        return "simulate";
    }

    @Override
    public String synopsis() {
        return "--seed S [--internal-seed I (default: S)] [--faults SET] [--png FILE] [--trace FILE.csv]"
                + " | --load FILE [--internal-seed I] [--faults SET] [--png FILE] [--trace FILE.csv]"
                + " | --maps N [--seed S0 (default: 1)] [--summary] [--gallery DIR] [--batch B (exec: only)];"
                + " any of them with [--controller builtin|exec:COMMAND] [--tick-timeout MS (default: "
                + ExecControllers.DEFAULT_TICK_TIMEOUT_MILLIS + ")] [--controller-log FILE];"
                + " or one run driven by recorded commands: (--seed S | --load FILE) --commands RECORDING.jsonl.gz"
                + " [--png FILE] [--trace FILE.csv]";
    }

    @Override
    public String summary() {
        return "simulate maps fault-free and print the outcome (one map, or --maps N in a row on one thread)";
    }

    /** The most runs --batch steps together. */
    static final int MAX_BATCH = 64;

    @Override
    public int run(List<String> args, PrintStream out, PrintStream err) throws UsageException {
        Options options = Options.parse(name(), args,
                Set.of("--seed", "--internal-seed", "--load", "--png", "--trace", "--maps", "--faults", "--gallery",
                        "--controller", "--tick-timeout", "--controller-log", "--batch", "--commands"),
                Set.of("--summary"));
        options.noPositional();
        if (options.has("--commands")) {
            return simulate(options, null, recording(options), out, err);
        }
        try (ControllerChoice.Workers controllers = controllers(options, err)) {
            Path log = options.outputFile("--controller-log").orElse(null);
            ControllerFactory factory = controllers.worker(log);
            if (options.has("--batch")) {
                int batch = options.count("--batch", 1, MAX_BATCH).orElseThrow();
                if (!options.has("--maps")) {
                    throw new UsageException("simulate: --batch B goes with --maps N: it steps B of the N runs together.");
                }
                BatchingProxy proxy;
                try {
                    proxy = controllers.batched(log, batch);
                } catch (ControllerStartException e) {
                    throw new UsageException("simulate: " + e.getMessage() + "; fix the command given to --controller.");
                }
                if (proxy == null) {
                    throw new UsageException("simulate: --batch B goes with --controller exec:COMMAND, a controller"
                            + " program; the others run in sitcov's process.");
                }
                try (proxy) {
                    if (proxy.batch() < batch) {
                        err.println("simulate: the controller takes " + proxy.batch() + " run" + (proxy.batch() == 1 ? "" : "s")
                                + " a message (its hello's \"batch\"): batches of " + proxy.batch());
                    }
                    return calibrate(options, factory, proxy, out, err);
                }
            }
            if (options.has("--maps")) {
                return calibrate(options, factory, null, out, err);
            }
            return simulate(options, factory, null, out, err);
        }
    }

    /** The recording --commands names, read and checked; refused with the options it cannot go with. */
    private static Recording recording(Options options) throws UsageException {
        for (String other : List.of("--controller", "--faults", "--maps", "--batch", "--tick-timeout", "--controller-log",
                "--gallery", "--summary")) {
            if (options.has(other)) {
                throw new UsageException("simulate: --commands drives the car from a recording, with no controller and no"
                        + " faults; drop " + other + ".");
            }
        }
        Path file = options.inputFile("--commands").orElseThrow();
        try {
            return RecordingFile.read(file);
        } catch (IOException | IllegalArgumentException e) {
            throw new UsageException("simulate: --commands " + file + ": " + e.getMessage()
                    + "; name a recording as sitcov wrote it (a results folder's recordings/*.jsonl.gz).");
        }
    }

    /** The controller --controller names, started once and handshaken before anything runs. */
    private ControllerChoice.Workers controllers(Options options, PrintStream err) throws UsageException {
        ControllerChoice choice;
        try {
            choice = ControllerChoice.parse(options.value("--controller").orElse("builtin"));
        } catch (IllegalArgumentException e) {
            throw new UsageException("simulate: --controller: " + e.getMessage() + ".");
        }
        int timeout = options.count("--tick-timeout", 1, Integer.MAX_VALUE)
                .orElse((int) ExecControllers.DEFAULT_TICK_TIMEOUT_MILLIS);
        ControllerChoice.Workers workers = choice.open(Version.current(), timeout,
                ExecControllers.DEFAULT_HANDSHAKE_TIMEOUT_MILLIS);
        try {
            String hello = workers.check(null);
            if (choice instanceof ControllerChoice.Exec) {
                err.println("simulate: controller " + hello + " (" + choice.text() + ")");
            }
        } catch (ControllerStartException e) {
            workers.close();
            throw new UsageException("simulate: " + e.getMessage() + "; fix the command given to --controller.");
        }
        return workers;
    }

    /** One run, of {@code controller}, or driven by {@code recorded}'s commands when it is not null. */
    private int simulate(Options options, ControllerFactory controller, Recording recorded, PrintStream out,
                         PrintStream err) throws UsageException {
        if (options.has("--summary") || options.has("--gallery")) {
            throw new UsageException("simulate: " + (options.has("--summary") ? "--summary" : "--gallery")
                    + " goes with --maps N; one run prints one line anyway (draw it with --png).");
        }
        Optional<Long> seed = options.seed("--seed");
        Optional<Long> internal = options.seed("--internal-seed");
        Optional<Path> load = options.inputFile("--load");
        if (seed.isPresent() == load.isPresent()) {
            throw new UsageException("simulate: give either --seed S to generate a map or --load FILE to read one"
                    + " (or --maps N for many).");
        }
        Set<Fault> faults = options.faults("--faults").orElse(Set.of());
        Optional<Path> png = options.outputFile("--png");
        Optional<Path> trace = options.outputFile("--trace");

        WorldMap map = seed.isPresent() ? MapGenerator.generate(seed.get()) : Situations.loadRunnable(name(), load.get());
        long internalSeed = internal.orElse(recorded != null ? recorded.internalSeed() : map.seed());
        if (recorded != null && (recorded.externalSeed() != map.seed() || recorded.internalSeed() != internalSeed)) {
            throw new UsageException("simulate: the recording " + options.value("--commands").orElseThrow() + " is of map "
                    + recorded.externalSeed() + " with internal seed " + recorded.internalSeed() + ", not of map "
                    + map.seed() + " with internal seed " + internalSeed + "; give its map (--seed "
                    + recorded.externalSeed() + ", or its situation file) and leave out --internal-seed.");
        }
        TrajectoryRecorder recorder = png.isPresent() ? new TrajectoryRecorder() : null;
        NearMissWatch nearMisses = new NearMissWatch();
        RunResult result;
        List<Activation> activations;
        // the builtin car's traces keep the columns they always had
        boolean builtin = recorded == null && options.value("--controller").orElse("builtin").equals("builtin");
        String[] firstClamp = new String[1];
        try (TraceWriter writer = trace.isPresent() ? new TraceWriter(trace.get(), map.seed(), internalSeed, !builtin) : null) {
            // why the controller failed, if it did: the outcome alone does not say
            String[] failure = new String[1];
            RunObserver observer = (tick, scene, detector) -> {
                if (scene.failure() != null) {
                    failure[0] = scene.failure().getMessage();
                }
                if (firstClamp[0] == null && scene.clamped()) {
                    firstClamp[0] = "tick " + tick + " (" + scene.clampNote() + ")";
                }
                nearMisses.afterTick(tick, scene, detector);
                if (recorder != null) {
                    recorder.afterTick(tick, scene, detector);
                }
                if (writer != null) {
                    writer.afterTick(tick, scene, detector);
                }
            };
            RunRecord record = recorded != null
                    ? Simulator.replay(map, internalSeed, recorded.commands(), recorded.stopAfter(), observer)
                    : Simulator.run(map, internalSeed, faults, observer, controller);
            result = record.result();
            activations = record.activations();
            if (failure[0] != null) {
                err.println("simulate: " + failure[0]);
            }
        } catch (IOException | UncheckedIOException e) {
            err.println("sitcov: simulate: could not write the trace " + trace.orElse(null) + ": "
                    + sitcov.results.IoReason.of(e instanceof UncheckedIOException u ? u.getCause() : (IOException) e,
                    trace.orElse(null)) + ".");
            return ExitCode.FAILURE;
        }
        out.println(resultLine(result));
        if (recorded != null && (result.outcome() != recorded.outcome() || result.ticks() != recorded.ticks())) {
            err.println("sitcov: simulate: the recording " + options.value("--commands").orElseThrow() + " ended in "
                    + recorded.outcome() + " after " + recorded.ticks() + " ticks, its replay in " + result.outcome()
                    + " after " + result.ticks() + ": the map or the world changed since it was recorded.");
            return ExitCode.FAILURE;
        }
        RunDetails.print(out, result, firstClamp[0], activations, nearMisses);
        trace.ifPresent(t -> out.println("Trace written to " + t + " (" + result.ticks() + " ticks, one row each)"));
        if (png.isPresent()) {
            try {
                RunRenderer renderer = new RunRenderer(PIXELS_PER_METRE);
                renderer.writePng(renderer.render(map, recorder, result), png.get());
            } catch (IOException e) {
                err.println("sitcov: simulate: could not write " + png.get() + ": " + sitcov.results.IoReason.of(e, png.get()) + ".");
                return ExitCode.FAILURE;
            }
            out.println("Run drawn to " + png.get());
        }
        return ExitCode.OK;
    }

    /** --maps N; with {@code batched} (--batch B), the runs are stepped B at a time over one controller process. */
    private int calibrate(Options options, ControllerFactory controller, BatchingProxy batched, PrintStream out,
                          PrintStream err) throws UsageException {
        for (String single : List.of("--internal-seed", "--load", "--png", "--trace", "--faults")) {
            if (options.has(single)) {
                throw new UsageException("simulate: " + single + " goes with one run, not with --maps N; drop it,"
                        + " or simulate one of the maps with --seed S.");
            }
        }
        int maps = options.count("--maps", 1, MAX_MAPS).orElseThrow();
        long first = options.firstSeed("--seed", maps);
        boolean perRun = !options.has("--summary");
        java.util.OptionalInt timeout = options.has("--tick-timeout")
                ? java.util.OptionalInt.of(options.count("--tick-timeout", 1, Integer.MAX_VALUE).orElseThrow())
                : java.util.OptionalInt.empty();
        String named = options.value("--controller").orElse("builtin");
        Calibration calibration = new Calibration(first, maps, !perRun, Calibration.controllerArgs(named, timeout),
                named.startsWith("builtin:"));
        RunGallery gallery = null;
        if (options.value("--gallery").isPresent()) {
            Path folder = Path.of(options.value("--gallery").get());
            if (Files.isRegularFile(folder) || (Files.isDirectory(folder) && !RunCommand.isEmpty(folder))) {
                throw new UsageException("simulate: --gallery " + Options.shown(folder) + " exists and is not an empty"
                        + " folder; name a new one.");
            }
            try {
                gallery = new RunGallery(folder, controller);
            } catch (IOException e) {
                throw new UsageException("simulate: cannot create the gallery folder " + Options.shown(folder) + ": "
                        + e.getMessage() + "; choose a writable folder.");
            }
        }
        Progress progress = new Progress(err, "simulate", maps,
                err == System.err && System.console() != null, System::nanoTime);
        // batched runs are run first, all of them; each is the run it would have been alone
        List<RunResult> results = batched == null ? null : BatchedRuns.run(maps, batched, (i, f) -> new LiveRun(
                MapGenerator.generate(first + i), first + i, Set.of(), f)).stream().map(RunRecord::result).toList();
        for (int i = 0; i < maps; i++) {
            long seed = first + i;
            WorldMap map = MapGenerator.generate(seed);
            RunResult result = results != null ? results.get(i)
                    : Simulator.run(map, seed, Set.of(), RunObserver.NONE, controller).result();
            calibration.add(result);
            if (gallery != null && RunGallery.wentWrong(result)) {
                try {
                    gallery.add(map, result);
                } catch (IOException e) {
                    err.println("sitcov: simulate: could not draw into the gallery: " + e.getMessage());
                    return ExitCode.FAILURE;
                }
            }
            if (perRun) {
                out.println(resultLine(result));
            }
            progress.done(i + 1);
        }
        if (perRun) {
            out.println();
        }
        calibration.printTable(out);
        if (gallery != null) {
            try {
                gallery.finish();
            } catch (IOException e) {
                err.println("sitcov: simulate: could not write the gallery's index: " + e.getMessage());
                return ExitCode.FAILURE;
            }
            out.println("Gallery: " + gallery.size() + " runs with an accident or a TIMEOUT drawn into "
                    + options.value("--gallery").get() + " (index.html, index.csv)");
        }
        return ExitCode.OK;
    }

    /** The one-line result of a run: both seeds, outcome, ticks and every accident event. */
    static String resultLine(RunResult r) {
        StringBuilder s = new StringBuilder()
                .append("seed ").append(r.externalSeed()).append(" internal ").append(r.internalSeed()).append(": ")
                .append(r.outcome()).append(" after ").append(r.ticks()).append(" ticks; accidents: ");
        if (r.accidents().isEmpty()) {
            s.append("none");
        } else {
            s.append(r.accidents().size()).append(" (")
                    .append(r.accidents().stream().map(SimulateCommand::describe).collect(Collectors.joining("; ")))
                    .append(')');
        }
        int excused = r.excusedContacts().values().stream().mapToInt(Integer::intValue).sum();
        if (excused > 0) {
            s.append("; excused contacts: ").append(excused);
        }
        if (r.clampedTicks() > 0) {
            s.append("; clamped ticks: ").append(r.clampedTicks());
        }
        return s.toString();
    }

    private static String describe(Accident a) {
        String where = String.format(Locale.ROOT, "%s t=%d at (%.1f, %.1f)", a.type(), a.tick(), a.x(), a.y());
        if (a.otherParty() < 0) {
            return where;
        }
        return where + " with " + (a.type() == AccidentType.CLASHWITHOBSTACLE ? "parked car "
                : a.type() == AccidentType.CLASHWITHOTHERCAR ? "moving car " : "party ") + a.otherParty();
    }
}
