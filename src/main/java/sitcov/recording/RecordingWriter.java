package sitcov.recording;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import sitcov.experiment.ExperimentEvent;
import sitcov.experiment.ExperimentListener;
import sitcov.experiment.MapRun;
import sitcov.judge.RunSummary;
import sitcov.judge.Variant;
import sitcov.results.OutputFile;
import sitcov.results.ResultsFolder;
import sitcov.vehicles.CommandLog;

/**
 * Writes a judged map's recordings into the results folder as the experiment goes, each file whole,
 * before the journal takes the map's rows: a row in runs.csv has its recording on disk, whatever kill
 * followed. A map cut short is judged again on resume and writes the same bytes again.
 */
public final class RecordingWriter implements ExperimentListener {
    private final Path folder;
    private final List<Variant> variants;

    public RecordingWriter(Path folder, List<Variant> variants) {
        this.folder = folder;
        this.variants = List.copyOf(variants);
    }

    @Override
    public void on(ExperimentEvent event) {
        if (!(event instanceof ExperimentEvent.MapJudged m) || m.resumed() || m.recordings().isEmpty()) {
            return;
        }
        try {
            Path dir = folder.resolve(ResultsFolder.RECORDINGS);
            Files.createDirectories(dir);
            // in run order, so that a kill leaves a prefix of the map's files
            for (Map.Entry<Integer, CommandLog> e : new java.util.TreeMap<>(m.recordings()).entrySet()) {
                Recording r = of(m.run(), e.getKey(), e.getValue());
                OutputFile.writeBytes(dir.resolve(r.key().fileName()), RecordingFile.write(r));
            }
        } catch (IOException e) {
            throw new UncheckedIOException("could not record a run in " + folder + ": " + e.getMessage(), e);
        }
    }

    /** The recording of run {@code index} of {@code map} (0 the reference, i variant i). */
    private Recording of(MapRun map, int index, CommandLog commands) {
        RunSummary run = index == 0 ? map.faultFree() : map.faults().get(index - 1).run();
        int variant = index == 0 ? Recording.RunKey.REFERENCE : variants.get(index - 1).id();
        return new Recording(new Recording.RunKey(map.replication(), map.driver(), map.mapIndex(), variant),
                map.externalSeed(), map.internalSeed(), run.outcome(), run.ticks(), commands);
    }
}
