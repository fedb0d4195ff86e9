package sitcov.cli;

import java.awt.GraphicsEnvironment;
import java.io.PrintStream;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import javax.swing.SwingUtilities;
import sitcov.builtin.BuiltinCar;
import sitcov.faults.Fault;
import sitcov.faults.FaultSet;
import sitcov.judge.LiveRun;
import sitcov.render.MapRenderer;
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
        return "--seed S [--internal-seed I (default: S)] [--faults SET] | --load FILE [--internal-seed I] [--faults SET]";
    }

    @Override
    public String summary() {
        return "watch a run live in a window (Swing): play, pause, step, speed, restart; a faulty run beside its twin";
    }

    @Override
    public int run(List<String> args, PrintStream out, PrintStream err) throws UsageException {
        Options options = Options.parse(name(), args, Set.of("--seed", "--internal-seed", "--load", "--faults"), Set.of());
        options.noPositional();
        Optional<Long> seed = options.seed("--seed");
        Optional<Path> load = options.inputFile("--load");
        if (seed.isPresent() == load.isPresent()) {
            throw new UsageException("view: give --seed S to generate a map or --load FILE to read one.");
        }
        WorldMap map = seed.isPresent() ? MapGenerator.generate(seed.get()) : Situations.loadRunnable("view", load.get());
        long internal = options.seed("--internal-seed").orElse(map.seed());
        Set<Fault> faults = options.faults("--faults").orElse(Set.of());
        if (GraphicsEnvironment.isHeadless()) {
            throw new UsageException("view: there is no display here; run it on a desktop, or under a virtual one"
                    + " (xvfb-run -a " + Main.LAUNCHER + " view ...), or draw the run with 'replay --seed S --fault F --gif FILE'.");
        }
        int panes = faults.isEmpty() ? 1 : 2;
        int scale = ViewerWindow.scaleFor(ViewerWindow.usableScreen().getSize(), panes, MapRenderer.DEFAULT_SCALE);
        String twin = faults.size() == 1 ? "without the fault" : "without the faults";
        SwingUtilities.invokeLater(() -> new ViewerWindow(() -> {
            List<RunPainter> painters = new ArrayList<>();
            if (!faults.isEmpty()) {
                painters.add(new RunPainter(new LiveRun(map, internal, Set.of(), BuiltinCar.FACTORY), twin, scale));
            }
            painters.add(new RunPainter(new LiveRun(map, internal, faults, BuiltinCar.FACTORY), faults.isEmpty() ? "seed " + map.seed()
                    : "with " + (faults.size() == 1 ? "fault " + faults.iterator().next().id() + " ("
                            + faults.iterator().next().label() + ")" : "faults " + FaultSet.format(faults)), scale));
            return painters;
        }).show());
        out.println("view: a window shows map " + map.seed() + " (internal seed " + internal + "); close it to end.");
        return ExitCode.OK;
    }
}
