package sitcov.report;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.Comparator;
import java.util.List;
import sitcov.experiment.DriverSpend;
import sitcov.experiment.ExperimentConfig;
import sitcov.experiment.Journal;
import sitcov.experiment.MapRun;

/**
 * Reads and writes the journal of a results folder: {@code runs.csv}, {@code drivers.csv} and
 * {@code timings.csv}. What a kill cut short is left out when reading; writing puts every row in
 * the canonical order (replication, then driver in the preset's order, then map), so the files
 * do not depend on which thread or shard finished first.
 */
public final class JournalFiles {
    private JournalFiles() {
    }

    /** Everything the folder's journal holds that was written whole. */
    public static Journal read(Path folder, ExperimentConfig config) throws IOException {
        RunsCsv runsCsv = new RunsCsv(config);
        List<MapRun> runs = runsCsv.read(text(folder, ResultsFolder.RUNS), folder.resolve(ResultsFolder.RUNS).toString());
        List<DriverSpend> spends = DriversCsv.read(text(folder, ResultsFolder.DRIVERS),
                folder.resolve(ResultsFolder.DRIVERS).toString());
        TimingsCsv.Times times = TimingsCsv.read(text(folder, ResultsFolder.TIMINGS),
                folder.resolve(ResultsFolder.TIMINGS).toString());
        Journal journal = Journal.empty();
        try {
            for (MapRun run : runs) {
                config.driverIndex(run.driver());
                long[] t = times.map(run.replication(), run.driver(), run.mapIndex());
                journal.add(new Journal.Entry(run, t[0], t[1]));
            }
            for (DriverSpend s : spends) {
                config.driverIndex(s.driver());
                journal.add(new Journal.Finished(s, times.done(s.replication(), s.driver())));
            }
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException(folder + ": " + e.getMessage(), e);
        }
        return journal;
    }

    private static String text(Path folder, String name) throws IOException {
        try {
            return Files.readString(folder.resolve(name), StandardCharsets.UTF_8);
        } catch (NoSuchFileException e) {
            throw new IllegalArgumentException(folder + " lacks " + name + "; it is not a results folder sitcov wrote");
        }
    }

    /** The journal's maps in runs.csv's order: by replication, then the preset's driver order, then map index. */
    static List<Journal.Entry> inOrder(ExperimentConfig config, Journal journal) {
        Comparator<MapRun> mapOrder = Comparator.comparingInt(MapRun::replication)
                .thenComparingInt(r -> config.driverIndex(r.driver())).thenComparingInt(MapRun::mapIndex);
        return journal.entries().stream().sorted(Comparator.comparing(Journal.Entry::run, mapOrder)).toList();
    }

    /** Writes the journal whole, in canonical order, replacing the folder's journal files. */
    public static void write(Path folder, ExperimentConfig config, Journal journal) throws IOException {
        RunsCsv runsCsv = new RunsCsv(config);
        List<Journal.Entry> entries = inOrder(config, journal);
        List<Journal.Finished> finished = journal.finished().stream()
                .sorted(Comparator.comparingInt((Journal.Finished f) -> f.spend().replication())
                        .thenComparingInt(f -> config.driverIndex(f.spend().driver()))).toList();
        StringBuilder runs = new StringBuilder(runsCsv.header()).append('\n');
        StringBuilder timings = new StringBuilder(TimingsCsv.HEADER).append('\n');
        for (Journal.Entry e : entries) {
            runs.append(runsCsv.block(e.run()));
            timings.append(TimingsCsv.mapRow(e.run().replication(), e.run().driver(), e.run().mapIndex(), e.mapNanos(),
                    e.driverNanos()));
        }
        StringBuilder drivers = new StringBuilder(DriversCsv.HEADER).append('\n');
        for (Journal.Finished f : finished) {
            drivers.append(DriversCsv.row(f.spend()));
            timings.append(TimingsCsv.doneRow(f.spend().replication(), f.spend().driver(), f.spend().mapsRun(),
                    f.driverNanos()));
        }
        OutputFile.writeString(folder.resolve(ResultsFolder.TIMINGS), timings.toString());
        OutputFile.writeString(folder.resolve(ResultsFolder.RUNS), runs.toString());
        OutputFile.writeString(folder.resolve(ResultsFolder.DRIVERS), drivers.toString());
    }
}
