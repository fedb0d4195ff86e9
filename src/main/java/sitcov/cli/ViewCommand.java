package sitcov.cli;

import java.awt.GraphicsEnvironment;
import java.io.PrintStream;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import java.util.function.IntFunction;
import javax.swing.SwingUtilities;
import sitcov.builtin.BuiltinCar;
import sitcov.faults.Fault;
import sitcov.faults.FaultSet;
import sitcov.judge.LiveRun;
import sitcov.recording.FolderRecordings;
import sitcov.recording.Recording;
import sitcov.recording.RecordingFile;
import sitcov.render.MapRenderer;
import sitcov.results.ResultsRows;
import sitcov.viewer.RunPainter;
import sitcov.viewer.ViewerWindow;
import sitcov.world.MapGenerator;
import sitcov.world.WorldMap;

/** {@code view}: a run in a window as it happens, beside its fault-free twin when faults are given. */
final class ViewCommand implements Command {
    @Override
    public String name() {
        return "view";
    }

    @Override
    public String synopsis() {
        return "--seed S [--internal-seed I (default: S)] [--faults SET] | --load FILE [--internal-seed I] [--faults SET]"
                + " | DIR --row N (a recorded row, replayed from its recordings)  [--png FILE [--tick T]] (no window:"
                + " the panes at tick T, default the last, painted into FILE)";
    }

    @Override
    public String summary() {
        return "watch a run live in a window (Swing): play, pause, step, speed, restart; a faulty run beside its twin";
    }

    @Override
    public int run(List<String> args, PrintStream out, PrintStream err) throws UsageException {
        Options options = Options.parse(name(), args, Set.of("--seed", "--internal-seed", "--load", "--faults", "--row",
                "--png", "--tick"), Set.of());
        if (options.has("--tick") && !options.has("--png")) {
            throw new UsageException("view: --tick T paints tick T into a picture: add --png FILE.");
        }
        if (!options.positional().isEmpty() || options.has("--row")) {
            return viewRow(options, out);
        }
        Optional<Long> seed = options.seed("--seed");
        Optional<Path> load = options.inputFile("--load");
        if (seed.isPresent() == load.isPresent()) {
            throw new UsageException("view: give --seed S to generate a map or --load FILE to read one.");
        }
        WorldMap map = seed.isPresent() ? MapGenerator.generate(seed.get()) : Situations.loadRunnable("view", load.get());
        long internal = options.seed("--internal-seed").orElse(map.seed());
        Set<Fault> faults = options.faults("--faults").orElse(Set.of());
        IntFunction<List<RunPainter>> painters = scale -> {
            List<RunPainter> panes = new ArrayList<>();
            if (!faults.isEmpty()) {
                panes.add(new RunPainter(new LiveRun(map, internal, Set.of(), BuiltinCar.FACTORY),
                        faults.size() == 1 ? "without the fault" : "without the faults", scale));
            }
            panes.add(new RunPainter(new LiveRun(map, internal, faults, BuiltinCar.FACTORY), faults.isEmpty() ? "seed " + map.seed()
                    : "with " + (faults.size() == 1 ? "fault " + faults.iterator().next().id() + " ("
                            + faults.iterator().next().label() + ")" : "faults " + FaultSet.format(faults)), scale));
            return panes;
        };
        if (options.has("--png")) {
            return painted(options, painters, "map " + map.seed() + " (internal seed " + internal + ")", out);
        }
        if (GraphicsEnvironment.isHeadless()) {
            throw new UsageException("view: there is no display here; run it on a desktop, or under a virtual one"
                    + " (xvfb-run -a " + Main.LAUNCHER + " view ...), or paint a tick with --png FILE --tick T, or draw"
                    + " the run with 'replay --seed S --fault F --gif FILE'.");
        }
        open(painters, faults.isEmpty() ? 1 : 2);
        out.println("view: a window shows map " + map.seed() + " (internal seed " + internal + "); close it to end.");
        return ExitCode.OK;
    }

    /** Opens the window, at the largest scale at which {@code panes} panes fit the screen. */
    private static void open(IntFunction<List<RunPainter>> painters, int panes) {
        int scale = ViewerWindow.scaleFor(ViewerWindow.usableScreen().getSize(), panes, MapRenderer.DEFAULT_SCALE);
        SwingUtilities.invokeLater(() -> new ViewerWindow(() -> painters.apply(scale)).show());
    }

    /** {@code --png FILE [--tick T]}: the panes as the window shows them at tick T (default: each run's last), no window. */
    private static int painted(Options options, IntFunction<List<RunPainter>> painters, String what, PrintStream out)
            throws UsageException {
        Path png = options.outputFile("--png").orElseThrow();
        long tick = options.count("--tick", 0, Integer.MAX_VALUE).map(Integer::longValue).orElse(Long.MAX_VALUE);
        List<RunPainter> panes = painters.apply(MapRenderer.DEFAULT_SCALE);
        for (RunPainter p : panes) {
            while (p.run().tick() < tick && p.history().step()) {
                // stepped as the window's Step button steps it
            }
        }
        try {
            MapRenderer.writeAtomically(ViewerWindow.frame(panes), png);
        } catch (java.io.IOException e) {
            throw new UsageException("view: could not write --png " + Options.shown(png) + ": " + e.getMessage() + ".");
        }
        out.println("view: " + what + " painted at tick " + panes.stream().map(p -> Long.toString(p.run().tick()))
                .collect(java.util.stream.Collectors.joining(" and ")) + " into " + png);
        return ExitCode.OK;
    }

    /** The panes of a recorded row: the reference's run and a variant's row's own, each driven by its recording. */
    static List<RunPainter> rowPainters(ResultsRows.Row row, WorldMap map, Recording reference, Optional<Recording> variant,
                                        int scale) {
        List<RunPainter> painters = new ArrayList<>();
        painters.add(new RunPainter(LiveRun.replaying(map, reference.internalSeed(), reference.commands(),
                reference.stopAfter()), "the reference, replayed", scale));
        variant.ifPresent(v -> painters.add(new RunPainter(LiveRun.replaying(map, v.internalSeed(), v.commands(),
                v.stopAfter()), "variant " + row.variant().get().id() + " (" + row.variant().get().label() + "), replayed",
                scale)));
        return painters;
    }

    /** {@code view DIR --row N}: the row's runs, each driven by its recorded commands, whatever controller made them. */
    private static int viewRow(Options options, PrintStream out) throws UsageException {
        if (options.positional().size() != 1 || !options.has("--row") || options.has("--seed") || options.has("--load")
                || options.has("--internal-seed") || options.has("--faults")) {
            throw new UsageException("view: name one results folder and a row of it: view DIR --row N [--png FILE"
                    + " [--tick T]].");
        }
        Path folder = Path.of(options.positional().get(0));
        ResultsRows.Row row;
        WorldMap map;
        Recording reference;
        Optional<Recording> variant;
        try {
            row = ResultsRows.row(folder, options.count("--row", 1, Integer.MAX_VALUE).orElseThrow());
            map = ResultsRows.worldMap(folder, row.map());
            if (!FolderRecordings.has(folder, row)) {
                throw new UsageException("view: row " + row.number() + " of " + folder + " has no recording (only runs that"
                        + " failed or found something are recorded, unless the experiment ran with --record all); watch"
                        + " its map with 'view --seed " + row.map().externalSeed() + " --internal-seed "
                        + row.map().internalSeed() + "'.");
            }
            // replayed once, checked against runs.csv, before the window opens
            FolderRecordings.replay(folder, row, map, sitcov.judge.RunObserver.NONE, sitcov.judge.RunObserver.NONE);
            reference = RecordingFile.read(FolderRecordings.file(folder, FolderRecordings.key(row, true)));
            variant = row.variant().isEmpty() ? Optional.empty()
                    : Optional.of(RecordingFile.read(FolderRecordings.file(folder, FolderRecordings.key(row, false))));
        } catch (java.io.IOException | IllegalArgumentException e) {
            throw new UsageException("view: " + e.getMessage() + ".");
        }
        IntFunction<List<RunPainter>> painters = scale -> rowPainters(row, map, reference, variant, scale);
        if (options.has("--png")) {
            return painted(options, painters, "row " + row.number() + " of " + folder + ", replayed from its recordings,",
                    out);
        }
        if (GraphicsEnvironment.isHeadless()) {
            throw new UsageException("view: there is no display here; run it on a desktop, or under a virtual one"
                    + " (xvfb-run -a " + Main.LAUNCHER + " view ...), or paint a tick with --png FILE --tick T, or draw the"
                    + " row with 'replay " + folder + " --row " + row.number() + " --gif FILE'.");
        }
        open(painters, variant.isEmpty() ? 1 : 2);
        out.println("view: a window shows row " + row.number() + " of " + folder + ", replayed from its recordings; close"
                + " it to end.");
        return ExitCode.OK;
    }
}
