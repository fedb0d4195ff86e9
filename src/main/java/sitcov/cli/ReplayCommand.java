package sitcov.cli;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import sitcov.builtin.BuiltinCar;
import sitcov.faults.Fault;
import sitcov.judge.FaultVerdict;
import sitcov.judge.FaultyRuns;
import sitcov.judge.JudgedMap;
import sitcov.judge.MapRunner;
import sitcov.judge.RunObserver;
import sitcov.judge.Simulator;
import sitcov.oracle.RunResult;
import sitcov.render.FrameRecorder;
import sitcov.render.OutcomeText;
import sitcov.render.ReplayAnimation;
import sitcov.render.ReplayPicture;
import sitcov.render.RowReplay;
import sitcov.render.RunRenderer;
import sitcov.recording.FolderRecordings;
import sitcov.render.TrajectoryRecorder;
import sitcov.results.ResultsRows;
import sitcov.world.MapGenerator;
import sitcov.world.WorldMap;

/**
 * {@code replay}: a recorded run (a row of a results folder) or a map and seeds, run again without
 * and with a fault and drawn side by side. A row is first judged again as the experiment judged it;
 * if the replay does not give exactly what {@code runs.csv} holds, it says so and fails.
 */
final class ReplayCommand implements Command {
    private static final int PIXELS_PER_METRE = 6;
    /** A frame each second of simulated time (5 ticks); the animation skips what does not move. */
    private static final int FRAME_TICKS = 5;

    @Override
    public String name() {
        return "replay";
    }

    @Override
    public String synopsis() {
        return "DIR --row N [--png FILE] [--gif FILE]\n"
                + "       " + Main.LAUNCHER + " replay DIR --replication R --driver D --map I [--fault F] [--png FILE]\n"
                + "       " + Main.LAUNCHER + " replay --seed S [--internal-seed I (default: S)] --fault F [--png FILE] [--gif FILE]\n"
                + "       " + Main.LAUNCHER + " replay --load FILE [--internal-seed I] --fault F [--png FILE] [--gif FILE]";
    }

    @Override
    public String summary() {
        return "run a recorded map (a row of runs.csv) or a map and seeds again, without and with a fault, side by side";
    }

    /** What to replay: the map, its internal seed, the fault (empty: fault-free only), and the row it must match. */
    private record Case(WorldMap map, long internalSeed, Optional<Fault> fault, FaultyRuns length,
                        Optional<ResultsRows.Row> row, Optional<Path> recordedIn, boolean drawnFromRecordings) {
    }

    @Override
    public int run(List<String> args, PrintStream out, PrintStream err) throws UsageException {
        Options options = Options.parse(name(), args, Set.of("--row", "--replication", "--driver", "--map", "--fault",
                "--seed", "--internal-seed", "--load", "--png", "--gif"), Set.of());
        Case c = options.positional().isEmpty() ? fromSeeds(options) : fromFolder(options);
        if (c.drawnFromRecordings()) {
            return fromRecordings(c, options, out, err);
        }
        String name = "replay-" + c.map().seed() + "-" + c.internalSeed() + c.fault().map(f -> "-fault-" + f.id()).orElse("")
                + ".png";
        Path png = options.outputFile("--png", Path.of(name));
        Optional<Path> gif = options.outputFile("--gif");
        JudgedMap judged = MapRunner.judge(c.map(), c.internalSeed(), c.fault().stream().toList(), c.length(),
                BuiltinCar.FACTORY);
        if (c.row().isPresent()) {
            Optional<String> differs = RecordedRows.differences(c.row().get(), judged);
            if (differs.isPresent()) {
                err.println("sitcov: replay: row " + c.row().get().number() + " does not replay: " + differs.get()
                        + ". Was the folder written by another version of sitcov? (see its manifest)");
                return ExitCode.FAILURE;
            }
            if (c.recordedIn().isPresent()) {
                try {
                    FolderRecordings.replay(c.recordedIn().get(), c.row().get(), c.map(), RunObserver.NONE, RunObserver.NONE);
                } catch (IllegalArgumentException | IOException e) {
                    err.println("sitcov: replay: " + e.getMessage() + ".");
                    return ExitCode.FAILURE;
                }
            }
            out.println("Row " + c.row().get().number() + " replays exactly as runs.csv recorded it.");
        }
        outcomes(c, judged, out);
        try {
            draw(c, judged, png, gif);
        } catch (IOException e) {
            err.println("sitcov: replay: could not write " + png + gif.map(g -> " or " + g).orElse("") + ": " + e.getMessage());
            return ExitCode.FAILURE;
        }
        out.println("Replay drawn to " + png + (c.fault().isPresent() ? " (left without the fault, right with it)" : ""));
        gif.ifPresent(g -> out.println("Animated in " + g));
        return ExitCode.OK;
    }

    /** A row the folder recorded, replayed from its recordings: no controller runs, builtin or not. */
    private static int fromRecordings(Case c, Options options, PrintStream out, PrintStream err) throws UsageException {
        ResultsRows.Row row = c.row().orElseThrow();
        Path folder = c.recordedIn().orElseThrow();
        String name = "replay-row-" + row.number() + ".png";
        Path png = options.outputFile("--png", Path.of(name));
        Optional<Path> gif = options.outputFile("--gif");
        RowReplay.Drawn drawn;
        try {
            drawn = RowReplay.of(folder, row, c.map(), PIXELS_PER_METRE, FRAME_TICKS).orElseThrow();
        } catch (IllegalArgumentException e) {
            err.println("sitcov: replay: " + e.getMessage() + ".");
            return ExitCode.FAILURE;
        } catch (IOException e) {
            throw new UsageException("replay: cannot read the recordings of row " + row.number() + " in " + folder + ": "
                    + e.getMessage() + ".");
        }
        out.println("Row " + row.number() + " replays exactly as runs.csv recorded it, from its recorded commands (no"
                + " controller ran).");
        RunResult base = drawn.runs().reference().result();
        String reference = OutcomeText.of(base.outcome(), base.ticks(), base.accidents());
        if (row.variant().isPresent()) {
            RunResult run = drawn.runs().variant().orElseThrow().result();
            out.println("With " + (row.fault().isPresent() ? "fault " : "variant ") + row.variant().get().id() + " ("
                    + row.variant().get().label() + "): " + OutcomeText.of(run.outcome(), run.ticks(), run.accidents())
                    + ". Verdict: " + drawn.verdict().orElseThrow());
            out.println((row.fault().isPresent() ? "Without the fault" : "The reference") + " (its twin, same map and"
                    + " internal seed): " + reference);
        } else {
            out.println("The reference's run: " + reference);
        }
        try {
            Files.createDirectories(png.toAbsolutePath().getParent());
            new RunRenderer(PIXELS_PER_METRE).writePng(drawn.picture(), png);
            if (gif.isPresent()) {
                ReplayAnimation.write(c.map(), drawn.sides(), gif.get());
            }
        } catch (IOException e) {
            err.println("sitcov: replay: could not write " + png + gif.map(g -> " or " + g).orElse("") + ": " + e.getMessage());
            return ExitCode.FAILURE;
        }
        out.println("Replay drawn to " + png + (row.fault().isPresent() ? " (left without the fault, right with it)"
                : row.variant().isPresent() ? " (left the reference, right the variant)" : ""));
        gif.ifPresent(g -> out.println("Animated in " + g));
        return ExitCode.OK;
    }

    /** How each run ended: the faulty run first, with its verdict, then its twin, each named as such. */
    private static void outcomes(Case c, JudgedMap judged, PrintStream out) {
        RunResult free = judged.faultFree();
        String twin = OutcomeText.of(free.outcome(), free.ticks(), free.accidents());
        if (c.fault().isEmpty()) {
            out.println("The fault-free run: " + twin);
            return;
        }
        FaultVerdict verdict = judged.verdicts().get(0);
        RunResult faulty = verdict.faultyRun();
        Fault fault = c.fault().get();
        out.println("With fault " + fault.id() + " (" + fault.label() + "): "
                + OutcomeText.of(faulty.outcome(), faulty.ticks(), faulty.accidents()) + ". Verdict: " + ReplayPicture.verdictLine(verdict, c.length()));
        out.println("Without the fault (its twin, same map and internal seed): " + twin);
    }

    private static void draw(Case c, JudgedMap judged, Path png, Optional<Path> gif) throws IOException {
        TrajectoryRecorder free = new TrajectoryRecorder();
        FrameRecorder freeFrames = new FrameRecorder(FRAME_TICKS);
        var faultFree = Simulator.run(c.map(), c.internalSeed(), Set.of(), both(free, freeFrames), BuiltinCar.FACTORY).result();
        var freeSide = new ReplayAnimation.Side(c.fault().isEmpty() ? "the fault-free run" : "without the fault", free,
                freeFrames.frames(), faultFree, Optional.empty(), Optional.empty());
        if (c.fault().isEmpty()) {
            RunRenderer renderer = new RunRenderer(PIXELS_PER_METRE);
            renderer.writePng(renderer.render(c.map(), free, faultFree), png);
            if (gif.isPresent()) {
                ReplayAnimation.write(c.map(), List.of(freeSide), gif.get());
            }
            return;
        }
        TrajectoryRecorder faulty = new TrajectoryRecorder();
        FrameRecorder faultyFrames = new FrameRecorder(FRAME_TICKS);
        // the picture follows the faulty run to its end, even where the experiment stopped it at its verdict
        var record = Simulator.run(c.map(), c.internalSeed(), Set.of(c.fault().get()), both(faulty, faultyFrames),
                BuiltinCar.FACTORY);
        FaultVerdict verdict = judged.verdicts().get(0);
        String line = ReplayPicture.verdictLine(verdict, c.length());
        var activation = record.activations().get(c.fault().get().ordinal());
        Files.createDirectories(png.toAbsolutePath().getParent());
        new RunRenderer(PIXELS_PER_METRE).writePng(new ReplayPicture(PIXELS_PER_METRE).render(c.map(),
                new ReplayPicture.Side(free, faultFree), new ReplayPicture.Side(faulty, record.result()),
                activation, line, verdict.newAccident()), png);
        if (gif.isPresent()) {
            ReplayAnimation.write(c.map(), List.of(freeSide, new ReplayAnimation.Side("with fault " + c.fault().get().id(),
                    faulty, faultyFrames.frames(), record.result(), Optional.of(activation), verdict.newAccident())),
                    gif.get());
        }
    }

    private static RunObserver both(RunObserver a, RunObserver b) {
        return (tick, scene, detector) -> {
            a.afterTick(tick, scene, detector);
            b.afterTick(tick, scene, detector);
        };
    }

    private static Case fromFolder(Options options) throws UsageException {
        if (options.positional().size() != 1 || options.has("--seed") || options.has("--load")
                || options.has("--internal-seed")) {
            throw new UsageException("replay: name one results folder and a row of it (--row N, or --replication R"
                    + " --driver D --map I [--fault F]); seeds and situation files are replayed without a folder.");
        }
        Path folder = Path.of(options.positional().get(0));
        try {
            ResultsRows.Row row;
            if (options.has("--row")) {
                if (options.has("--replication") || options.has("--driver") || options.has("--map") || options.has("--fault")) {
                    throw new UsageException("replay: --row N names the run whole; drop --replication, --driver, --map"
                            + " and --fault.");
                }
                row = ResultsRows.row(folder, options.count("--row", 1, Integer.MAX_VALUE).orElseThrow());
            } else {
                if (!options.has("--replication") || !options.has("--driver") || !options.has("--map")) {
                    throw new UsageException("replay: name the run with --row N (the row of runs.csv under its header),"
                            + " or with --replication R --driver D --map I [--fault F].");
                }
                row = ResultsRows.find(folder, options.count("--replication", 0, Integer.MAX_VALUE).orElseThrow(),
                        options.value("--driver").orElseThrow(), options.count("--map", 0, Integer.MAX_VALUE).orElseThrow(),
                        oneFault(options, false).map(Fault::id));
            }
            WorldMap map = ResultsRows.worldMap(folder, row.map());
            boolean recorded = FolderRecordings.has(folder, row);
            // the builtin car is always at hand and draws the faulty run on to its end, past where the
            // experiment stopped it; its recordings are checked all the same
            if (!recorded || RecordedRows.ofTheBuiltinCar(row)) {
                RecordedRows.refuseOtherController("replay", folder, row);
            }
            return new Case(map, row.map().internalSeed(), row.fault(), row.config().faultyRuns(), Optional.of(row),
                    recorded ? Optional.of(folder) : Optional.empty(), recorded && !RecordedRows.ofTheBuiltinCar(row));
        } catch (IOException | IllegalArgumentException e) {
            throw new UsageException("replay: " + e.getMessage() + ".");
        }
    }

    private static Case fromSeeds(Options options) throws UsageException {
        Optional<Long> seed = options.seed("--seed");
        Optional<Path> load = options.inputFile("--load");
        if (seed.isPresent() == load.isPresent()) {
            throw new UsageException("replay: give a results folder and a row, or --seed S, or --load FILE.");
        }
        WorldMap map = seed.isPresent() ? MapGenerator.generate(seed.get()) : Situations.loadRunnable("replay", load.get());
        return new Case(map, options.seed("--internal-seed").orElse(map.seed()), oneFault(options, true),
                FaultyRuns.TO_END, Optional.empty(), Optional.empty(), false);
    }

    private static Optional<Fault> oneFault(Options options, boolean required) throws UsageException {
        Optional<Set<Fault>> faults = options.faults("--fault");
        if (faults.isEmpty() && !required) {
            return Optional.empty();
        }
        if (faults.isEmpty() || faults.get().size() != 1) {
            throw new UsageException("replay: --fault names one fault to run beside the fault-free run, e.g. --fault 17.");
        }
        return Optional.of(faults.get().iterator().next());
    }
}
