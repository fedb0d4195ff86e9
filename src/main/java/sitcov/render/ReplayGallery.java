package sitcov.render;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import sitcov.control.ControllerFactory;
import sitcov.experiment.ExperimentConfig;
import sitcov.experiment.MapRun;
import sitcov.faults.Fault;
import sitcov.judge.FaultVerdict;
import sitcov.judge.JudgedMap;
import sitcov.judge.MapRunner;
import sitcov.judge.Variant;
import sitcov.results.ResultsFolder;
import sitcov.results.ResultsRows;

/**
 * The report's pictures of failures and findings, in {@code replays/}: a reference's own failure alone,
 * a variant's finding beside the reference's run of the same map. Which rows are drawn is the report's
 * choice; each is drawn from the folder's recordings, so no controller runs.
 */
public final class ReplayGallery {
    private static final int PIXELS_PER_METRE = 4;

    private ReplayGallery() {
    }

    /**
     * A row to draw: its number in runs.csv, its map, its variant (empty for the reference's own failure),
     * and whether it is its variant's first finding (drawn as {@code fault-ID.png}, as reports always named it;
     * every other picture is {@code row-N.png}).
     */
    public record Pictured(int row, MapRun run, Optional<Variant> variant, boolean first) {
        /** Its file, relative to the results folder, with {@code /} between the parts (as a page links it). */
        public String name() {
            return ResultsFolder.REPLAYS + "/" + (first ? "fault-" + variant.orElseThrow().id() : "row-" + row) + ".png";
        }

        public Path file(Path folder) {
            return folder.resolve(name());
        }
    }

    /**
     * Draws the pictures: a seeded fault of the builtin car by the builtin car ({@code builtin}) run again to the
     * end of the faulty run (its recording ends where the experiment stopped it); every other row, of any
     * controller, replayed from its recordings. A row without recordings (a folder written before them) is
     * not drawn.
     */
    public static void write(Path folder, ExperimentConfig config, List<Pictured> rows, ControllerFactory builtin)
            throws IOException {
        boolean builtinCar = config.controller().equals(ExperimentConfig.BUILTIN);
        // each picture is its own file, judged and drawn alone: drawing them side by side changes no byte
        try {
            rows.parallelStream().forEach(p -> {
                try {
                    if (builtinCar && p.variant().orElse(null) instanceof Variant.Seeded seeded) {
                        draw(folder, config, p, seeded.fault(), builtin);
                    } else {
                        drawRecorded(folder, p);
                    }
                } catch (IOException e) {
                    throw new UncheckedIOException(e);
                }
            });
        } catch (UncheckedIOException e) {
            throw e.getCause();
        }
    }

    /** The row replayed from the folder's recordings: the reference's run alone, or beside it the variant's. */
    private static void drawRecorded(Path folder, Pictured p) throws IOException {
        ResultsRows.Row r = ResultsRows.row(folder, p.row());
        var drawn = RowReplay.of(folder, r, ResultsRows.worldMap(folder, r.map()), PIXELS_PER_METRE, Integer.MAX_VALUE);
        if (drawn.isPresent()) {
            write(drawn.get().picture(), p.file(folder));
        }
    }

    private static void draw(Path folder, ExperimentConfig config, Pictured p, Fault fault, ControllerFactory builtin)
            throws IOException {
        MapRun run = p.run();
        var map = ResultsRows.worldMap(folder, run);
        JudgedMap judged = MapRunner.judge(map, run.internalSeed(), List.of(fault), config.faultyRuns(), builtin);
        FaultVerdict verdict = judged.verdicts().get(0);
        write(new ReplayPicture(PIXELS_PER_METRE).render(map, run.internalSeed(), verdict, config.faultyRuns(), builtin),
                p.file(folder));
    }

    private static void write(java.awt.image.BufferedImage picture, Path file) throws IOException {
        Files.createDirectories(file.getParent());
        MapRenderer.writeAtomically(picture, file);
    }
}
