package sitcov.render;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import sitcov.control.ControllerFactory;
import sitcov.experiment.ExperimentConfig;
import sitcov.experiment.MapRun;
import sitcov.faults.Fault;
import sitcov.judge.FaultVerdict;
import sitcov.judge.JudgedMap;
import sitcov.judge.MapRunner;
import sitcov.judge.Notion;
import sitcov.judge.Variant;
import sitcov.results.ResultsFolder;
import sitcov.results.ResultsRows;

/**
 * The replay picture of the first map that found each fault, for the report: {@code replays/fault-N.png}
 * (a bounded number: one a fault, so a large experiment's report stays quick to write and to open).
 */
public final class ReplayGallery {
    private static final int PIXELS_PER_METRE = 4;

    private ReplayGallery() {
    }

    public static Path picture(Path folder, Variant variant) {
        return folder.resolve(ResultsFolder.REPLAYS).resolve("fault-" + variant.id() + ".png");
    }

    /** Draws the pictures of a folder of the builtin car; {@code builtin} makes its runs (a folder of another controller has none). */
    public static void write(Path folder, ExperimentConfig config, List<MapRun> inOrder, ControllerFactory builtin)
            throws IOException {
        if (!config.controller().equals(ExperimentConfig.BUILTIN)) {
            // the pictures run the builtin car; a folder that tested another controller shows none
            return;
        }
        List<Variant> faults = config.variants();
        List<Runnable> pictures = new ArrayList<>();
        for (int f = 0; f < faults.size(); f++) {
            for (MapRun run : inOrder) {
                if (faults.get(f) instanceof Variant.Seeded seeded && run.faults().get(f).found(Notion.DIFFERENTIAL)) {
                    Fault fault = seeded.fault();
                    pictures.add(() -> {
                        try {
                            draw(folder, config, run, fault, builtin);
                        } catch (IOException e) {
                            throw new UncheckedIOException(e);
                        }
                    });
                    break;
                }
            }
        }
        // each picture is its own file, judged and drawn alone: drawing them side by side changes no byte
        try {
            pictures.parallelStream().forEach(Runnable::run);
        } catch (UncheckedIOException e) {
            throw e.getCause();
        }
    }

    private static void draw(Path folder, ExperimentConfig config, MapRun run, Fault fault, ControllerFactory builtin)
            throws IOException {
        var map = ResultsRows.worldMap(folder, run);
        JudgedMap judged = MapRunner.judge(map, run.internalSeed(), List.of(fault), config.faultyRuns(), builtin);
        FaultVerdict verdict = judged.verdicts().get(0);
        Path file = picture(folder, new Variant.Seeded(fault));
        Files.createDirectories(file.getParent());
        MapRenderer.writeAtomically(new ReplayPicture(PIXELS_PER_METRE).render(map, run.internalSeed(), verdict,
                config.faultyRuns(), builtin), file);
    }
}
