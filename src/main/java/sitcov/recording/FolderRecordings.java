package sitcov.recording;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Optional;
import sitcov.judge.DifferentialOracle;
import sitcov.judge.FaultOutcome;
import sitcov.judge.FaultVerdict;
import sitcov.judge.RunObserver;
import sitcov.judge.RunRecord;
import sitcov.judge.RunSummary;
import sitcov.judge.Simulator;
import sitcov.judge.Variant;
import sitcov.results.ResultsFolder;
import sitcov.results.ResultsRows;
import sitcov.world.WorldMap;

/**
 * A results folder's recordings, found by row of runs.csv and replayed: the car driven from the
 * recorded commands, no controller needed, each replay checked to end as runs.csv recorded it (the
 * outcome, the tick, the accidents and the margins), or refused naming the row.
 */
public final class FolderRecordings {
    private FolderRecordings() {
    }

    /** A row replayed: the reference's run, and the variant's with its verdict when the row is a variant's. */
    public record Replayed(RunRecord reference, Optional<RunRecord> variant, Optional<FaultVerdict> verdict) {
    }

    /** The file of the run {@code key} in {@code folder}. */
    public static Path file(Path folder, Recording.RunKey key) {
        return folder.resolve(ResultsFolder.RECORDINGS).resolve(key.fileName());
    }

    /** The key of {@code row}'s reference run ({@code reference}) or of its own run. */
    public static Recording.RunKey key(ResultsRows.Row row, boolean reference) {
        int variant = reference ? Recording.RunKey.REFERENCE : row.variant().map(Variant::id).orElse(Recording.RunKey.REFERENCE);
        return new Recording.RunKey(row.map().replication(), row.map().driver(), row.map().mapIndex(), variant);
    }

    /** Whether the folder keeps the recordings {@code row}'s replay needs: its own run's and its reference's. */
    public static boolean has(Path folder, ResultsRows.Row row) {
        return Files.isRegularFile(file(folder, key(row, true))) && Files.isRegularFile(file(folder, key(row, false)));
    }

    /**
     * The row's runs replayed from their recordings, each watched by its observer, each checked against
     * runs.csv; empty when the folder keeps no recording of the row (its runs passed, or the folder was
     * written before recordings).
     *
     * @throws IllegalArgumentException naming the row when a recording is damaged or does not replay as recorded
     */
    public static Optional<Replayed> replay(Path folder, ResultsRows.Row row, WorldMap map, RunObserver reference,
                                            RunObserver variant) throws IOException {
        if (!has(folder, row)) {
            return Optional.empty();
        }
        RunRecord base = run(folder, row, map, key(row, true), row.map().faultFree(), reference);
        if (row.variant().isEmpty()) {
            return Optional.of(new Replayed(base, Optional.empty(), Optional.empty()));
        }
        FaultOutcome was = row.outcome().orElseThrow();
        RunRecord run = run(folder, row, map, key(row, false), was.run(), variant);
        FaultVerdict verdict = DifferentialOracle.judge(base.result(), run.result(), row.variant().get(), was.reached(),
                was.effective() ? 1 : 0, was.firstEffectiveTick());
        FaultOutcome now = FaultOutcome.of(verdict);
        if (!was.agrees(now)) {
            throw new IllegalArgumentException("row " + row.number() + " does not replay from its recordings in " + folder
                    + ": runs.csv holds " + was.detection() + was.newAccident().map(f -> " by " + f).orElse("")
                    + ", the replay gives " + now.detection() + now.newAccident().map(f -> " by " + f).orElse("")
                    + "; the folder or the world changed");
        }
        return Optional.of(new Replayed(base, Optional.of(run), Optional.of(verdict)));
    }

    private static RunRecord run(Path folder, ResultsRows.Row row, WorldMap map, Recording.RunKey key, RunSummary recorded,
                                 RunObserver observer) throws IOException {
        Path file = file(folder, key);
        Recording r = RecordingFile.read(file);
        if (!r.key().equals(key) || r.externalSeed() != row.map().externalSeed()
                || r.internalSeed() != row.map().internalSeed()) {
            throw new IllegalArgumentException("the recording " + file + " is of another run (" + r.key() + ", seeds "
                    + r.externalSeed() + "/" + r.internalSeed() + "), not of row " + row.number() + "; put the folder back"
                    + " as sitcov wrote it");
        }
        RunRecord replayed = Simulator.replay(map, r.internalSeed(), r.commands(), r.stopAfter(), observer);
        RunSummary now = RunSummary.of(replayed.result());
        if (r.outcome() != recorded.outcome() || r.ticks() != recorded.ticks() || !recorded.agrees(now)) {
            throw new IllegalArgumentException("row " + row.number() + " does not replay from its recording " + file
                    + ": " + (key.variant() == Recording.RunKey.REFERENCE ? "the reference's" : "the variant's")
                    + " run was recorded in runs.csv as " + words(recorded) + ", the recording says " + r.outcome()
                    + " after " + r.ticks() + " ticks, and it replays to " + words(now)
                    + "; the folder or the world changed (was the folder written by another version of sitcov? see its"
                    + " manifest)");
        }
        return replayed;
    }

    private static String words(RunSummary r) {
        return r.outcome() + " after " + r.ticks() + " ticks (accidents " + r.accidents() + ")";
    }
}
