package sitcov.render;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import sitcov.faults.Activation;
import sitcov.judge.FaultVerdict;
import sitcov.judge.RunObserver;
import sitcov.judge.Variant;
import sitcov.recording.FolderRecordings;
import sitcov.results.ResultsRows;
import sitcov.world.WorldMap;

/**
 * A row of a results folder replayed from its recordings, whatever controller ran it, and drawn: the
 * reference's run alone, or beside it the variant's, as {@code replay} and the report show them.
 */
public final class RowReplay {
    private RowReplay() {
    }

    /**
     * The row drawn: its picture, its sides to animate, the verdict in one line (empty for a
     * reference's row) and the runs replayed.
     */
    public record Drawn(BufferedImage picture, List<ReplayAnimation.Side> sides, Optional<String> verdict,
                        FolderRecordings.Replayed runs) {
    }

    /**
     * The row replayed and drawn at {@code pixelsPerMetre}, with a frame every {@code frameTicks} ticks;
     * empty when the folder keeps no recording of it.
     *
     * @throws IllegalArgumentException naming the row when it does not replay as recorded
     */
    public static Optional<Drawn> of(Path folder, ResultsRows.Row row, WorldMap map, int pixelsPerMetre, int frameTicks)
            throws IOException {
        TrajectoryRecorder basePath = new TrajectoryRecorder();
        FrameRecorder baseFrames = new FrameRecorder(frameTicks);
        TrajectoryRecorder path = new TrajectoryRecorder();
        FrameRecorder frames = new FrameRecorder(frameTicks);
        Optional<FolderRecordings.Replayed> replayed = FolderRecordings.replay(folder, row, map,
                both(basePath, baseFrames), both(path, frames));
        if (replayed.isEmpty()) {
            return Optional.empty();
        }
        FolderRecordings.Replayed runs = replayed.get();
        var base = runs.reference().result();
        if (runs.variant().isEmpty()) {
            BufferedImage alone = new ReplayPicture(pixelsPerMetre).render(map, new ReplayPicture.Side(basePath, base),
                    "the reference's run, replayed from its recorded commands",
                    OutcomeText.of(base.outcome(), base.ticks(), base.accidents()));
            return Optional.of(new Drawn(alone, List.of(new ReplayAnimation.Side(
                    "the reference's run", basePath, baseFrames.frames(), base, Optional.empty(), Optional.empty())),
                    Optional.empty(), runs));
        }
        Variant variant = row.variant().orElseThrow();
        FaultVerdict verdict = runs.verdict().orElseThrow();
        var run = runs.variant().get().result();
        String line = ReplayPicture.verdictLine(verdict, row.config().faultyRuns());
        Optional<Activation> activation = verdict.activation();
        boolean seeded = variant instanceof Variant.Seeded;
        ReplayPicture.Titles titles = seeded ? new ReplayPicture.Titles("without the fault", "with fault " + variant.id()
                + " (" + variant.label() + ")", "the same map and internal seed; the runs part where the fault first acts")
                : ReplayPicture.Titles.ofVariant(variant);
        BufferedImage picture = new ReplayPicture(pixelsPerMetre).render(map, new ReplayPicture.Side(basePath, base),
                new ReplayPicture.Side(path, run), titles, activation, line, verdict.newAccident());
        List<ReplayAnimation.Side> sides = List.of(
                new ReplayAnimation.Side(titles.left(), basePath, baseFrames.frames(), base, Optional.empty(), Optional.empty()),
                new ReplayAnimation.Side((seeded ? "with fault " : "variant ") + variant.id(), path, frames.frames(), run,
                        activation, verdict.newAccident()));
        return Optional.of(new Drawn(picture, sides, Optional.of(line), runs));
    }

    static RunObserver both(RunObserver a, RunObserver b) {
        return (tick, run, detector) -> {
            a.afterTick(tick, run, detector);
            b.afterTick(tick, run, detector);
        };
    }
}
