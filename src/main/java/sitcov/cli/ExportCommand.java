package sitcov.cli;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import java.util.function.Supplier;
import sitcov.builtin.BuiltinCar;
import sitcov.export.OpenDrive;
import sitcov.export.OpenScenario;
import sitcov.export.RunRecording;
import sitcov.export.ScenarioVersion;
import sitcov.faults.Fault;
import sitcov.oracle.Accident;
import sitcov.results.IoReason;
import sitcov.results.OutputFile;
import sitcov.world.MapGenerator;
import sitcov.world.WorldMap;

/**
 * {@code export}: a map, its situation, a recorded run or every run of a results folder that found a
 * fault, as OpenDRIVE and OpenSCENARIO files a simulator plays (src/main/java/sitcov/export/README.md, "Export to
 * OpenDRIVE and OpenSCENARIO"). Every file is planned before any is written: an existing one stops the export
 * with nothing written.
 */
final class ExportCommand implements Command {
    static final String INDEX = "index.csv";

    @Override
    public String name() {
        return "export";
    }

    @Override
    public String synopsis() {
        return "--seed S --out DIR [--record [--internal-seed I] [--fault F]] [--osc 1.0|1.1|1.2|1.3]\n"
                + "       " + Main.LAUNCHER + " export --load FILE --out DIR [--record [--internal-seed I] [--fault F]] [--osc V]\n"
                + "       " + Main.LAUNCHER + " export RESULTS --row N --out DIR [--osc V]\n"
                + "       " + Main.LAUNCHER + " export RESULTS --found [--fault F] --out DIR [--osc V]";
    }

    @Override
    public String summary() {
        return "write a map, its situation, a recorded run or a folder's failing runs as OpenDRIVE and OpenSCENARIO"
                + " files (esmini, CARLA ScenarioRunner)";
    }

    /** One file the export will write: its name in the output folder and how to make its text. */
    record Planned(String name, Supplier<String> text) {
    }

    /** What an export will write, and what to say once it is written into a folder. */
    record Plan(List<Planned> files, java.util.function.Function<Path, String> done) {
    }

    @Override
    public int run(List<String> args, PrintStream out, PrintStream err) throws UsageException {
        Options options = Options.parse(name(), args, Set.of("--seed", "--load", "--out", "--row", "--fault",
                "--internal-seed", "--osc"), Set.of("--found", "--record"));
        ScenarioVersion version = version(options);
        Path folder = outFolder(options);
        Plan plan;
        try {
            plan = options.positional().isEmpty() ? MapExport.plan(options, version) : FolderExport.plan(options, version, err);
        } catch (RowMismatch e) {
            err.println("sitcov: export: " + e.getMessage() + " Nothing was written.");
            return ExitCode.FAILURE;
        }
        for (Planned p : plan.files()) {
            Path file = folder.resolve(p.name());
            if (Files.exists(file, java.nio.file.LinkOption.NOFOLLOW_LINKS)) {
                throw new UsageException("export: " + file + " already exists; remove it or choose another --out"
                        + " (nothing was written).");
            }
        }
        try {
            Files.createDirectories(folder);
            for (Planned p : plan.files()) {
                OutputFile.writeString(folder.resolve(p.name()), p.text().get());
            }
        } catch (IOException e) {
            err.println("sitcov: export: could not write into " + folder + ": " + IoReason.of(e, folder)
                    + "; files written before it are whole.");
            return ExitCode.FAILURE;
        } catch (IllegalStateException e) {
            // a hand-made situation the formats cannot carry, such as two junction squares that touch
            err.println("sitcov: export: cannot write this map: " + e.getMessage() + "; files written before it are whole.");
            return ExitCode.FAILURE;
        }
        out.println(plan.done().apply(folder));
        return ExitCode.OK;
    }

    /** A recorded row that does not run again as it was recorded: the folder came from another sitcov. */
    static final class RowMismatch extends RuntimeException {
        private static final long serialVersionUID = 1L;

        RowMismatch(String message) {
            super(message, null, false, false);
        }
    }

    private static ScenarioVersion version(Options options) throws UsageException {
        Optional<String> asked = options.value("--osc");
        if (asked.isEmpty()) {
            return ScenarioVersion.V1_0;
        }
        return ScenarioVersion.parse(asked.get()).orElseThrow(() -> new UsageException("export: --osc "
                + asked.get() + " is no OpenSCENARIO version sitcov writes; give 1.0 (the default, what CARLA reads),"
                + " 1.1, 1.2 or 1.3."));
    }

    private static Path outFolder(Options options) throws UsageException {
        Path folder = Path.of(options.value("--out").orElseThrow(() ->
                new UsageException("export: name the folder to write into with --out DIR.")));
        if (Files.exists(folder) && !Files.isDirectory(folder)) {
            throw new UsageException("export: --out " + folder + " is a file; name a folder (it is made if missing).");
        }
        // a folder under a file cannot be made: said before anything is written
        for (Path above = folder.toAbsolutePath().getParent(); above != null; above = above.getParent()) {
            if (Files.exists(above)) {
                if (!Files.isDirectory(above)) {
                    throw new UsageException("export: --out " + folder + " cannot be made: " + above + " is a file; name a"
                            + " folder under a folder (nothing was written).");
                }
                break;
            }
        }
        return folder;
    }

    /** The situation (and recorded runs) of a map: both read the same road file. */
    static List<Planned> mapFiles(String base, WorldMap map, ScenarioVersion version) {
        List<Planned> files = new ArrayList<>();
        files.add(new Planned(base + ".xodr", () -> OpenDrive.document(map)));
        if (map.layout().isRunnable()) {
            files.add(new Planned(base + ".xosc", () -> OpenScenario.situation(map, base + ".xodr", version)));
        }
        return files;
    }

    /** The builtin car's run recorded; {@code found}, the accident that found its fault, is marked in it. */
    static Planned recording(String name, String roadFile, WorldMap map, long internalSeed, Set<Fault> faults,
                             Optional<Accident> found, ScenarioVersion version) {
        return new Planned(name, () -> OpenScenario.recording(RunRecording.of(map, internalSeed, faults, BuiltinCar.FACTORY),
                found, roadFile, version));
    }

    /** {@code --seed S} or {@code --load FILE}: the map, its situation, and with {@code --record} a run of it. */
    private static final class MapExport {
        static Plan plan(Options options, ScenarioVersion version) throws UsageException {
            Optional<Long> seed = options.seed("--seed");
            Optional<Path> load = options.inputFile("--load");
            if (seed.isPresent() == load.isPresent() || options.has("--row") || options.has("--found")) {
                throw new UsageException("export: give --seed S or --load FILE (a map), or a results folder with"
                        + " --row N or --found.");
            }
            if (!options.has("--record") && (options.has("--internal-seed") || options.has("--fault"))) {
                throw new UsageException("export: --internal-seed and --fault choose the run that --record records;"
                        + " add --record.");
            }
            WorldMap map = seed.isPresent() ? MapGenerator.generate(seed.get()) : Situations.load("export", load.get());
            String base = seed.isPresent() ? "map-" + seed.get() : stem(load.get());
            List<Planned> files = new ArrayList<>(mapFiles(base, map, version));
            if (options.has("--record")) {
                if (!map.layout().isRunnable()) {
                    throw new UsageException("export: the map has no Target or no car start, so there is no run to"
                            + " --record; export it without --record.");
                }
                long internal = options.seed("--internal-seed").orElse(map.seed());
                Set<Fault> faults = options.faults("--fault").orElse(Set.of());
                String name = base + "-run-" + internal + (faults.isEmpty() ? "" : "-fault-" + String.join("-",
                        faults.stream().map(f -> Integer.toString(f.id())).sorted().toList())) + ".xosc";
                files.add(recording(name, base + ".xodr", map, internal, faults, Optional.empty(), version));
            }
            String note = map.layout().isRunnable() ? "" : " (no situation: the map has no Target or no car start)";
            return new Plan(files, to -> "Exported " + String.join(", ", files.stream().map(Planned::name).toList())
                    + " to " + to + note + ".");
        }

        private static String stem(Path file) {
            String name = file.getFileName().toString();
            int dot = name.lastIndexOf('.');
            return dot > 0 ? name.substring(0, dot) : name;
        }
    }
}
