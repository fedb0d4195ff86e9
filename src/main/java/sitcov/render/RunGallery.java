package sitcov.render;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.TreeSet;
import sitcov.control.ControllerFactory;
import sitcov.judge.Simulator;
import sitcov.oracle.Accident;
import sitcov.oracle.Outcome;
import sitcov.oracle.RunResult;
import sitcov.results.OutputFile;
import sitcov.world.WorldMap;

/**
 * A folder of pictures of the runs that went wrong (any accident or a TIMEOUT), each named by its
 * seeds and outcome, with {@code index.csv} and {@code index.html} listing them: for looking at
 * the car's failures one by one.
 */
public final class RunGallery {
    private static final int PIXELS_PER_METRE = 6;

    private final Path folder;
    private final ControllerFactory controller;
    private final List<String> rows = new ArrayList<>();
    private final List<String> files = new ArrayList<>();

    /** A gallery in {@code folder} of runs the controller {@code controller} makes. */
    public RunGallery(Path folder, ControllerFactory controller) throws IOException {
        this.folder = folder;
        this.controller = controller;
        Files.createDirectories(folder);
    }

    /** Whether a run belongs in the gallery. */
    public static boolean wentWrong(RunResult r) {
        return r.hasAccident() || r.outcome() == Outcome.TIMEOUT;
    }

    /** Runs the map again with a recorder (runs are deterministic) and draws it. */
    public void add(WorldMap map, RunResult result) throws IOException {
        TrajectoryRecorder recorder = new TrajectoryRecorder();
        RunResult again = Simulator.run(map, result.internalSeed(), Set.of(), recorder, controller).result();
        if (!again.equals(result)) {
            throw new IllegalStateException("map " + map.seed() + " internal seed " + result.internalSeed()
                    + " did not run the same way twice: " + result + " then " + again);
        }
        Set<String> types = new TreeSet<>();
        for (Accident a : result.accidents()) {
            types.add(a.type().name().toLowerCase(Locale.ROOT));
        }
        String name = "seed-" + map.seed() + "-internal-" + result.internalSeed() + "-" + result.outcome().name()
                .toLowerCase(Locale.ROOT) + (types.isEmpty() ? "" : "-" + String.join("-", types)) + ".png";
        RunRenderer renderer = new RunRenderer(PIXELS_PER_METRE);
        renderer.writePng(renderer.render(map, recorder, result), folder.resolve(name));
        files.add(name);
        rows.add(name + "," + map.seed() + "," + result.internalSeed() + "," + result.outcome() + "," + result.ticks() + ","
                + String.join(" ", types));
    }

    public int size() {
        return files.size();
    }

    /** Writes the index of what was drawn. */
    public void finish() throws IOException {
        List<String> csv = new ArrayList<>();
        csv.add("file,external_seed,internal_seed,outcome,ticks,accident_types");
        csv.addAll(rows);
        OutputFile.writeLines(folder.resolve("index.csv"), csv);
        StringBuilder html = new StringBuilder("<!doctype html><meta charset=utf-8><title>sitcov gallery</title>\n"
                + "<style>body{font-family:sans-serif}figure{display:inline-block;margin:8px}img{width:600px}</style>\n"
                + "<h1>Runs with an accident or a TIMEOUT: " + files.size() + "</h1>\n");
        for (String f : files) {
            html.append("<figure><a href=\"").append(f).append("\"><img src=\"").append(f).append("\" alt=\"").append(f)
                    .append("\"></a><figcaption>").append(f).append("</figcaption></figure>\n");
        }
        OutputFile.writeString(folder.resolve("index.html"), html.toString());
    }
}
