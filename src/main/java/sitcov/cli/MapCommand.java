package sitcov.cli;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import sitcov.render.MapRenderer;
import sitcov.results.IoReason;
import sitcov.results.OutputFile;
import sitcov.world.MapDescription;
import sitcov.world.MapGenerator;
import sitcov.world.SituationFile;
import sitcov.world.WorldMap;

/** {@code map}: generate a map from a seed (or load a situation file), describe it, save it, draw it. */
final class MapCommand implements Command {
    @Override
    public String name() {
        return "map";
    }

    @Override
    public String synopsis() {
        return "--seed S [--png FILE] [--save FILE] | --load FILE [--png FILE] | --check FILE...";
    }

    @Override
    public String summary() {
        return "generate a map, describe it, save it as a situation file, render it to PNG";
    }

    @Override
    public int run(List<String> args, PrintStream out, PrintStream err) throws UsageException {
        Options options = Options.parse(name(), args, Set.of("--seed", "--load", "--png", "--save"), Set.of("--check"));
        if (options.has("--check")) {
            return check(options, out, err);
        }
        options.noPositional();
        Optional<Long> seed = options.seed("--seed");
        Optional<Path> load = options.inputFile("--load");
        if (seed.isPresent() == load.isPresent()) {
            throw new UsageException("map: give either --seed S to generate a map or --load FILE to read one.");
        }
        if (load.isPresent() && options.has("--save")) {
            throw new UsageException("map: --save goes with --seed; a loaded map is already in its file.");
        }
        Optional<Path> png = options.outputFile("--png");
        Optional<Path> save = options.outputFile("--save");

        WorldMap map = seed.isPresent() ? MapGenerator.generate(seed.get()) : Situations.load(name(), load.get());
        out.println(MapDescription.of(map));
        Optional<Path> writing = save;
        try {
            if (save.isPresent()) {
                OutputFile.writeString(save.get(), SituationFile.format(map));
                out.println("Situation written to " + save.get());
            }
            writing = png;
            if (png.isPresent()) {
                new MapRenderer().writePng(map, png.get());
                out.println("Map drawn to " + png.get());
            }
        } catch (IOException e) {
            Path file = writing.orElseThrow();
            err.println("sitcov: map: could not write " + (file == save.orElse(null) ? "--save " : "--png ") + file + ": "
                    + IoReason.of(e, file) + ".");
            return ExitCode.FAILURE;
        }
        return ExitCode.OK;
    }

    /** {@code map --check FILE...}: reads every situation file and says which are refused, and why. */
    private int check(Options options, PrintStream out, PrintStream err) throws UsageException {
        for (String other : List.of("--seed", "--load", "--png", "--save")) {
            if (options.has(other)) {
                throw new UsageException("map: --check takes situation files only; drop " + other + ".");
            }
        }
        if (options.positional().isEmpty()) {
            throw new UsageException("map: --check needs situation files, e.g. 'map --check maps/*.situation'.");
        }
        int refused = 0;
        for (String name : options.positional()) {
            try {
                WorldMap map = Situations.load("map", Path.of(name));
                out.println(name + ": ok (" + map.layout().roads().size() + " roads, " + map.layout().parkedCars().size()
                        + " parked cars, " + map.movingCars().size() + " moving cars"
                        + (map.layout().isRunnable() ? "" : "; no Target or car start, so it cannot be run") + ")");
            } catch (UsageException e) {
                refused++;
                err.println("sitcov: " + e.getMessage());
            } catch (java.nio.file.InvalidPathException e) {
                refused++;
                err.println("sitcov: map: '" + name + "' is not a valid path.");
            }
        }
        int files = options.positional().size();
        out.println((files - refused) + " of " + files + " situation files are valid" + (refused > 0 ? "; " + refused
                + " refused (see above)" : ""));
        return refused > 0 ? ExitCode.USAGE : ExitCode.OK;
    }
}
