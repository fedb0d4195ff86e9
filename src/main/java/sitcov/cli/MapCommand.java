package sitcov.cli;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import sitcov.report.MapRenderer;
import sitcov.world.MapDescription;
import sitcov.world.MapGenerator;
import sitcov.world.SituationFile;
import sitcov.world.SituationFormatException;
import sitcov.world.WorldMap;

/** {@code map}: generate a map from a seed (or load a situation file), describe it, save it, draw it. */
final class MapCommand implements Command {
    @Override
    public String name() {
        return "map";
    }

    @Override
    public String synopsis() {
        return "--seed S [--png FILE] [--save FILE] | --load FILE [--png FILE]";
    }

    @Override
    public String summary() {
        return "generate a map, describe it, save it as a situation file, render it to PNG";
    }

    @Override
    public int run(List<String> args, PrintStream out, PrintStream err) throws UsageException {
        Options options = Options.parse(name(), args, Set.of("--seed", "--load", "--png", "--save"), Set.of());
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

        WorldMap map = seed.isPresent() ? MapGenerator.generate(seed.get()) : load(load.get());
        out.println(MapDescription.of(map));
        try {
            if (save.isPresent()) {
                SituationFile.write(map, save.get());
                out.println("Situation written to " + save.get());
            }
            if (png.isPresent()) {
                new MapRenderer().writePng(map, png.get());
                out.println("Map drawn to " + png.get());
            }
        } catch (IOException e) {
            err.println("sitcov: map: could not write: " + e.getMessage());
            return ExitCode.FAILURE;
        }
        return ExitCode.OK;
    }

    private static WorldMap load(Path file) throws UsageException {
        try {
            return SituationFile.read(file);
        } catch (SituationFormatException e) {
            throw new UsageException("map: " + e.getMessage());
        } catch (IOException e) {
            throw new UsageException("map: cannot read " + file + ": " + e.getMessage());
        }
    }
}
