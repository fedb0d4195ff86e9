package sitcov.cli;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.Set;
import sitcov.coverage.CoverageGrid;
import sitcov.coverage.GridDefinition;
import sitcov.figures.CoverageHeatMap;
import sitcov.results.IoReason;
import sitcov.world.MapGenerator;

/** {@code coverage --maps N}: how many cells of the situation grid N random maps reach, without simulating them. */
final class CoverageCommand implements Command {
    /** Counting is streamed; past this a run takes minutes for nothing the grid does not show already. */
    static final int MAX_MAPS = 10_000_000;
    private static final int PROGRESS_EVERY = 1000;

    @Override
    public String name() {
        return "coverage";
    }

    @Override
    public String synopsis() {
        return "--maps N [--seed S0 (default: 1)] [--grid FILE (default: the paper's 6x6x6)] [--png FILE]";
    }

    @Override
    public String summary() {
        return "situation coverage reached by N random maps (no simulation), optionally as heat-map slices";
    }

    @Override
    public int run(List<String> args, PrintStream out, PrintStream err) throws UsageException {
        Options options = Options.parse(name(), args, Set.of("--maps", "--seed", "--grid", "--png"), Set.of());
        options.noPositional();
        int maps = options.count("--maps", 1, MAX_MAPS).orElseThrow(() -> new UsageException(
                "coverage: give --maps N, the number of random maps to place in the grid (e.g. 20000)."));
        long first = options.firstSeed("--seed", maps);
        GridDefinition definition = grid(options.inputFile("--grid"));
        Optional<Path> png = options.outputFile("--png");
        CoverageGrid grid = new CoverageGrid(definition);
        Progress progress = new Progress(err, "coverage", maps, err == System.err && System.console() != null,
                System::nanoTime);
        for (int i = 0; i < maps; i++) {
            int cell = definition.cellOf(definition.values(MapGenerator.layout(first + i)));
            grid.add(cell);
            // a map takes well under a millisecond: telling a console of every one would cost more than the map
            if ((i + 1) % PROGRESS_EVERY == 0 || i + 1 == maps) {
                progress.done(i + 1);
            }
        }
        out.printf(Locale.ROOT, "Situation coverage of maps %d..%d (%s)%n", first, first + maps - 1,
                options.value("--grid").orElse("the paper's grid"));
        out.printf(Locale.ROOT, "  cells covered   %d of %d (%.1f%%)%n", grid.covered(), grid.cells(),
                100.0 * grid.covered() / grid.cells());
        out.printf(Locale.ROOT, "  invalid maps    %d (a criterion outside every bin)%n", grid.invalid());
        for (int k = 0; k < definition.criteria().size(); k++) {
            StringBuilder s = new StringBuilder();
            int bins = definition.bins().get(k).count();
            int[] perBin = new int[bins];
            for (int c = 0; c < grid.cells(); c++) {
                perBin[definition.binOf(c, k)] += grid.count(c);
            }
            for (int b = 0; b < bins; b++) {
                s.append(String.format(Locale.ROOT, " %5.1f%%", 100.0 * perBin[b] / maps));
            }
            out.printf(Locale.ROOT, "  %-26s maps per bin:%s%n", definition.criteria().get(k).key(), s);
        }
        if (png.isPresent()) {
            try {
                CoverageHeatMap.writePng(grid, String.format(Locale.ROOT, "Situation coverage of %d random maps (seeds %d..%d)",
                        maps, first, first + maps - 1), png.get());
            } catch (IOException e) {
                err.println("sitcov: coverage: could not write --png " + png.get() + ": " + IoReason.of(e, png.get()) + ".");
                return ExitCode.FAILURE;
            }
            out.println("Heat map written to " + png.get());
        }
        return ExitCode.OK;
    }

    private static GridDefinition grid(Optional<Path> file) throws UsageException {
        if (file.isEmpty()) {
            return GridDefinition.paper();
        }
        try {
            return GridDefinition.read(file.get());
        } catch (IllegalArgumentException e) {
            throw new UsageException("coverage: " + e.getMessage());
        } catch (IOException e) {
            throw new UsageException("coverage: cannot read the grid " + file.get() + ": " + IoReason.of(e, file.get()) + ".");
        }
    }
}
