package sitcov.results;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import sitcov.experiment.ExperimentEvent;
import sitcov.experiment.ExperimentListener;
import sitcov.experiment.MapId;
import sitcov.world.SituationFile;

/**
 * Appends to a results folder's journal as the experiment goes: a built map's situation file, its
 * timing row, then its block of runs.csv rows, each flushed at once and every row with its check
 * ({@link JournalCheck}), so a killed run keeps every map it judged whole. (A map whose block is cut
 * short is judged again on resume.) Replayed events are already on disk.
 */
public final class JournalWriter implements ExperimentListener, AutoCloseable {
    private final Path folder;
    private final RunsCsv runsCsv;
    private final JournalCheck check;
    private final Writer runs;
    private final Writer drivers;
    private final Writer timings;

    /** Opens the folder's journal files to append; they must exist, with their headers. */
    public JournalWriter(Path folder, Manifest manifest) throws IOException {
        this.folder = folder;
        this.runsCsv = new RunsCsv(manifest.config());
        this.check = JournalCheck.of(manifest);
        this.runs = append(folder.resolve(ResultsFolder.RUNS));
        this.drivers = append(folder.resolve(ResultsFolder.DRIVERS));
        this.timings = append(folder.resolve(ResultsFolder.TIMINGS));
    }

    private static Writer append(Path file) throws IOException {
        return Files.newBufferedWriter(file, StandardCharsets.UTF_8, StandardOpenOption.APPEND);
    }

    @Override
    public void on(ExperimentEvent event) {
        try {
            if (event instanceof ExperimentEvent.MapJudged m && !m.resumed()) {
                String situationCheck = "";
                if (m.run().map() instanceof MapId.Situation s) {
                    Path file = ResultsFolder.situation(folder, s.name());
                    if (m.builtSituation().isPresent()) {
                        String text = SituationFile.format(m.builtSituation().get());
                        // a map judged again on resume rewrites its own file; another map's is never replaced
                        if (Files.exists(file) && !Files.readString(file, StandardCharsets.UTF_8).equals(text)) {
                            throw new IllegalStateException(file + " holds another situation of that name, from an"
                                    + " earlier map of this experiment; driver " + m.run().driver() + " in replication "
                                    + m.run().replication() + " may not replace it: a built situation's name must be"
                                    + " unique in the experiment (name it by driver and replication)");
                        }
                        Files.createDirectories(file.getParent());
                        OutputFile.writeString(file, text);
                    }
                    situationCheck = JournalCheck.crc(Files.readAllBytes(file));
                }
                write(timings, check.rows(TimingsCsv.mapRow(m.run().replication(), m.run().driver(), m.run().mapIndex(),
                        m.mapNanos(), m.driverNanos())));
                write(runs, check.rows(runsCsv.block(m.run()), situationCheck));
            } else if (event instanceof ExperimentEvent.DriverDone d && !d.resumed()) {
                write(timings, check.rows(TimingsCsv.doneRow(d.spend().replication(), d.spend().driver(), d.spend().mapsRun(),
                        d.driverNanos())));
                write(drivers, check.rows(DriversCsv.row(d.spend())));
            }
        } catch (IOException e) {
            throw new UncheckedIOException("could not add to the journal in " + folder + ": " + e.getMessage(), e);
        }
    }

    private static void write(Writer w, String text) throws IOException {
        w.write(text);
        w.flush();
    }

    @Override
    public void close() throws IOException {
        try (runs; drivers; timings) {
            // closing all three, even if one fails
        }
    }
}
