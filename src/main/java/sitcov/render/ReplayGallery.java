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

    /**
     * Draws the pictures: in a folder of the builtin car, its runs made again by {@code builtin}; in a
     * folder of any other controller, its runs replayed from their recordings (no controller runs).
     */
    public static void write(Path folder, ExperimentConfig config, List<MapRun> inOrder, ControllerFactory builtin)
            throws IOException {
        boolean builtinCar = config.controller().equals(ExperimentConfig.BUILTIN);
        List<Variant> faults = config.variants();
        int perMap = 1 + faults.size();
        List<Runnable> pictures = new ArrayList<>();
        for (int f = 0; f < faults.size(); f++) {
            for (int m = 0; m < inOrder.size(); m++) {
                MapRun run = inOrder.get(m);
                if (!run.faults().get(f).found(Notion.DIFFERENTIAL)) {
                    continue;
                }
                Variant variant = faults.get(f);
                int row = m * perMap + f + 2;
                if (builtinCar && variant instanceof Variant.Seeded seeded) {
                    pictures.add(() -> unchecked(() -> draw(folder, config, run, seeded.fault(), builtin)));
                } else {
                    pictures.add(() -> unchecked(() -> drawRecorded(folder, variant, row)));
                }
                break;
            }
        }
        // each picture is its own file, judged and drawn alone: drawing them side by side changes no byte
        try {
            pictures.parallelStream().forEach(Runnable::run);
        } catch (UncheckedIOException e) {
            throw e.getCause();
        }
    }

    private interface Drawing {
        void draw() throws IOException;
    }

    private static void unchecked(Drawing d) {
        try {
            d.draw();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** The picture of row {@code row}, its variant beside the reference, replayed from the folder's recordings. */
    private static void drawRecorded(Path folder, Variant variant, int row) throws IOException {
        ResultsRows.Row r = ResultsRows.row(folder, row);
        var drawn = RowReplay.of(folder, r, ResultsRows.worldMap(folder, r.map()), PIXELS_PER_METRE, Integer.MAX_VALUE);
        if (drawn.isEmpty()) {
            return; // a folder written before recordings: its runs cannot be made again here
        }
        Path file = picture(folder, variant);
        Files.createDirectories(file.getParent());
        MapRenderer.writeAtomically(drawn.get().picture(), file);
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
