package sitcov.report;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;
import java.util.function.LongSupplier;
import sitcov.analysis.Summary;
import sitcov.control.ControllerFactory;
import sitcov.experiment.ExperimentEvent;
import sitcov.experiment.ExperimentListener;
import sitcov.experiment.Journal;
import sitcov.results.DriversCsv;
import sitcov.results.FolderLock;
import sitcov.results.JournalCheck;
import sitcov.results.JournalFiles;
import sitcov.results.JournalWriter;
import sitcov.results.Manifest;
import sitcov.results.OutputFile;
import sitcov.results.ResultsFolder;
import sitcov.results.RunsCsv;
import sitcov.results.TimingsCsv;

/**
 * The listener that keeps an experiment's results folder: it journals every judged map as it
 * comes and, when the experiment ends, completes the folder ({@link ResultsFinisher}). Made for a
 * fresh folder ({@link #create}) or for one a killed run left ({@link #resume}).
 */
public final class ResultsRecorder implements ExperimentListener {
    private final Path folder;
    private final Manifest manifest;
    private final Journal journal;
    private final Map<String, String> execution;
    private final LongSupplier nanoClock;
    private final long start;
    private final FolderLock lock;
    /** Makes the replay pictures' runs when the folder is finished (the builtin car's; see {@link ResultsFinisher#finish}). */
    private final ControllerFactory builtin;
    private JournalWriter writer;
    private final sitcov.recording.RecordingWriter recordings;
    private Summary summary;

    private ResultsRecorder(Path folder, FolderLock lock, Manifest manifest, Journal journal,
                            Map<String, String> execution, LongSupplier nanoClock, ControllerFactory builtin)
            throws IOException {
        this.folder = folder;
        this.builtin = builtin;
        this.lock = lock;
        this.manifest = manifest;
        this.journal = journal;
        this.execution = new LinkedHashMap<>(execution);
        this.nanoClock = nanoClock;
        this.start = nanoClock.getAsLong();
        this.writer = new JournalWriter(folder, manifest);
        this.recordings = new sitcov.recording.RecordingWriter(folder, manifest.config().variants());
    }

    /**
     * Claims an empty (or new) folder: its manifest, marked incomplete, and empty journal files.
     * {@code execution} holds what the folder's execution.properties should say (threads, JDK, ...);
     * {@code builtin} makes the runs of a builtin folder's replay pictures when it is finished.
     *
     * @throws IllegalStateException when another run holds the folder
     * @throws IllegalArgumentException when the folder holds files already
     */
    public static ResultsRecorder create(Path folder, Manifest manifest, Map<String, String> execution,
                                         LongSupplier nanoClock, ControllerFactory builtin) throws IOException {
        Files.createDirectories(folder);
        FolderLock lock = FolderLock.claim(folder);
        if (!ResultsFolder.holdsNothing(folder)) {
            lock.close();
            throw new IllegalArgumentException(folder + " holds files already; results never overwrite earlier ones");
        }
        // what a run killed before it wrote anything left
        ResultsFolder.sweepTemporaries(folder);
        JournalCheck check = JournalCheck.of(manifest);
        try {
            OutputFile.writeString(folder.resolve(ResultsFolder.RUNS), check.header(new RunsCsv(manifest.config()).header(),
                    true) + "\n");
            OutputFile.writeString(folder.resolve(ResultsFolder.DRIVERS), check.header(DriversCsv.HEADER, false) + "\n");
            OutputFile.writeString(folder.resolve(ResultsFolder.TIMINGS), check.header(TimingsCsv.HEADER, false) + "\n");
            // the manifest last: a folder that has one has its journal files too
            manifest.complete(false).write(folder);
            return new ResultsRecorder(folder, lock, manifest, Journal.empty(), execution, nanoClock, builtin);
        } catch (IOException | RuntimeException e) {
            lock.close(); // a full disk must not leave the folder claimed
            throw e;
        }
    }

    /**
     * Takes up a folder a killed run left: sweeps the temporary files the kill left, keeps what its
     * journal holds whole (rewritten without what the kill cut short) and continues it. A journal or
     * situation file changed by hand is refused. The manifest says so when that changes the results.
     */
    public static ResultsRecorder resume(Path folder, Manifest manifest, Map<String, String> execution,
                                         LongSupplier nanoClock, ControllerFactory builtin) throws IOException {
        FolderLock lock = FolderLock.claim(folder);
        Journal journal;
        try {
            ResultsFolder.sweepTemporaries(folder);
            journal = JournalFiles.read(folder, manifest);
        } catch (IOException | RuntimeException e) {
            lock.close();
            throw e;
        }
        JournalFiles.write(folder, manifest, journal);
        Manifest resumed = manifest.resumedRun();
        resumed.write(folder);
        Map<String, String> facts = new LinkedHashMap<>(execution);
        facts.put("resumed_with_maps", Integer.toString(journal.size()));
        return new ResultsRecorder(folder, lock, resumed, journal, facts, nanoClock, builtin);
    }

    /** What the folder already held: the runner replays it instead of simulating again. */
    public Journal journal() {
        return journal;
    }

    public Manifest manifest() {
        return manifest;
    }

    /** The summary of the complete folder, once the experiment ended. */
    public Summary summary() {
        if (summary == null) {
            throw new IllegalStateException("the experiment has not ended");
        }
        return summary;
    }

    /** @throws FolderLock.Lost at the first event after the folder was deleted, before anything is written */
    @Override
    public void on(ExperimentEvent event) {
        lock.verify();
        recordings.on(event); // before the journal: a row on disk has its recording
        writer.on(event);
        if (event instanceof ExperimentEvent.Ended) {
            try {
                writer.close();
                writer = null;
                execution.put("wall_seconds", String.format(Locale.ROOT, "%.1f", (nanoClock.getAsLong() - start) / 1e9));
                summary = ResultsFinisher.finish(folder, manifest, JournalFiles.read(folder, manifest), execution, builtin);
                lock.close();
            } catch (IOException e) {
                throw new UncheckedIOException("could not complete the results in " + folder + ": " + e.getMessage(), e);
            }
        }
    }

    /** Closes the journal files and gives up the folder (after a halt, or when done). */
    public void close() throws IOException {
        try {
            if (writer != null) {
                writer.close();
                writer = null;
            }
        } finally {
            lock.close();
        }
    }

    /** Whether {@code folder} holds an experiment's manifest that is marked complete. */
    public static boolean isComplete(Path folder) throws IOException {
        Path m = folder.resolve(ResultsFolder.MANIFEST);
        return Files.isRegularFile(m) && Files.readString(m, StandardCharsets.UTF_8).contains("\ncomplete=true\n");
    }
}
