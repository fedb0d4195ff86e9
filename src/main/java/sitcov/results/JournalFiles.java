package sitcov.results;

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
import sitcov.experiment.MapId;
import sitcov.experiment.MapRun;

/**
 * Reads and writes the journal of a results folder: {@code runs.csv}, {@code drivers.csv} and
 * {@code timings.csv}, every row checked ({@link JournalCheck}). What a kill cut short is left out
 * when reading; writing puts every row in the canonical order (replication, then driver in the
 * preset's order, then map), so the files do not depend on which thread or shard finished first.
 */
public final class JournalFiles {
    private JournalFiles() {
    }

    /**
     * Everything the folder's journal holds that was written whole, checked against the manifest
     * (see {@link JournalCheck}). In an incomplete folder a kill may have cut the last row or map
     * block short: it is left out, to be judged again. A complete folder was written whole, so
     * anything cut short there is refused.
     *
     * @throws IllegalArgumentException naming the file and line (or situation file) that was changed
     */
    public static Journal read(Path folder, Manifest manifest) throws IOException {
        ExperimentConfig config = manifest.config();
        JournalCheck check = JournalCheck.of(manifest);
        String fix = "put the folder back as sitcov wrote it, or run the experiment again into a new folder: "
                + manifest.rerun(folder);
        RunsCsv runsCsv = new RunsCsv(config);
        Path runsFile = folder.resolve(ResultsFolder.RUNS);
        JournalCheck.Checked runLines = lines(folder, ResultsFolder.RUNS, check, manifest.complete(), fix);
        List<MapRun> runs = runsCsv.read(runLines.lines(), runsFile.toString(), fix);
        int perMap = 1 + config.variants().size();
        if (manifest.complete() && runLines.lines().size() != 1 + runs.size() * perMap) {
            throw new IllegalArgumentException(runsFile + ":" + (2 + runs.size() * perMap) + ": a map's block of rows is cut"
                    + " short, in a folder that was complete; " + fix);
        }
        if (check.active()) {
            checkSituations(folder, runs, runLines.situationChecks(), perMap, fix);
        }
        List<DriverSpend> spends = DriversCsv.read(lines(folder, ResultsFolder.DRIVERS, check, manifest.complete(), fix)
                .lines(), folder.resolve(ResultsFolder.DRIVERS).toString(), fix);
        TimingsCsv.Times times = TimingsCsv.read(lines(folder, ResultsFolder.TIMINGS, check, manifest.complete(), fix)
                .lines(), folder.resolve(ResultsFolder.TIMINGS).toString(), fix);
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

    /** A journal file's whole lines, checked; in a complete folder a line cut short is refused. */
    private static JournalCheck.Checked lines(Path folder, String name, JournalCheck check, boolean complete, String fix)
            throws IOException {
        String text = text(folder, name);
        List<String> lines = CsvLines.complete(text);
        String source = folder.resolve(name).toString();
        if (complete && !text.isEmpty() && !text.endsWith("\n")) {
            throw new IllegalArgumentException(source + ":" + (lines.size() + 1) + ": the last line is cut short, in a folder"
                    + " that was complete; " + fix);
        }
        if (!check.active() && !lines.isEmpty() && lines.get(0).endsWith("," + JournalCheck.CHECK)) {
            throw new IllegalArgumentException(folder.resolve(ResultsFolder.MANIFEST) + " has lost its '" + Manifest.CHECKS
                    + "' line, but " + name + " has checks: the manifest was changed after sitcov wrote it; " + fix);
        }
        return check.read(lines, source, name.equals(ResultsFolder.RUNS), fix);
    }

    /** Every kept situation file must be the one its map was judged on: present and with its recorded check. */
    private static void checkSituations(Path folder, List<MapRun> runs, List<String> checks, int perMap, String fix)
            throws IOException {
        Path runsFile = folder.resolve(ResultsFolder.RUNS);
        for (int i = 0; i < runs.size(); i++) {
            if (!(runs.get(i).map() instanceof MapId.Situation s)) {
                continue;
            }
            int line = 2 + i * perMap;
            String recorded = checks.get(i * perMap);
            Path file = ResultsFolder.situation(folder, s.name());
            String now;
            try {
                now = JournalCheck.crc(Files.readAllBytes(file));
            } catch (NoSuchFileException e) {
                throw new IllegalArgumentException(file + " is missing, but " + runsFile + ":" + line + " names it; " + fix);
            }
            if (!now.equals(recorded)) {
                throw new IllegalArgumentException(file + " was changed after sitcov wrote it (it does not match the check"
                        + " in " + runsFile + ":" + line + "); " + fix);
            }
        }
    }

    private static String text(Path folder, String name) throws IOException {
        try {
            return Files.readString(folder.resolve(name), StandardCharsets.UTF_8);
        } catch (NoSuchFileException e) {
            throw new IllegalArgumentException(folder + " lacks " + name + "; it is not a results folder sitcov wrote");
        }
    }

    /** The check of a map's kept situation file, empty for a generated map. */
    private static String situationCheck(Path folder, MapRun run) throws IOException {
        return run.map() instanceof MapId.Situation s
                ? JournalCheck.crc(Files.readAllBytes(ResultsFolder.situation(folder, s.name()))) : "";
    }

    /** The journal's maps in runs.csv's order: by replication, then the preset's driver order, then map index. */
    public static List<Journal.Entry> inOrder(ExperimentConfig config, Journal journal) {
        Comparator<MapRun> mapOrder = Comparator.comparingInt(MapRun::replication)
                .thenComparingInt(r -> config.driverIndex(r.driver())).thenComparingInt(MapRun::mapIndex);
        return journal.entries().stream().sorted(Comparator.comparing(Journal.Entry::run, mapOrder)).toList();
    }

    /** Writes the journal whole, in canonical order, replacing the folder's journal files. */
    public static void write(Path folder, Manifest manifest, Journal journal) throws IOException {
        ExperimentConfig config = manifest.config();
        JournalCheck check = JournalCheck.of(manifest);
        RunsCsv runsCsv = new RunsCsv(config);
        List<Journal.Entry> entries = inOrder(config, journal);
        List<Journal.Finished> finished = journal.finished().stream()
                .sorted(Comparator.comparingInt((Journal.Finished f) -> f.spend().replication())
                        .thenComparingInt(f -> config.driverIndex(f.spend().driver()))).toList();
        StringBuilder runs = new StringBuilder(check.header(runsCsv.header(), true)).append('\n');
        StringBuilder timings = new StringBuilder(check.header(TimingsCsv.HEADER, false)).append('\n');
        for (Journal.Entry e : entries) {
            runs.append(check.rows(runsCsv.block(e.run()), check.active() ? situationCheck(folder, e.run()) : null));
            timings.append(check.rows(TimingsCsv.mapRow(e.run().replication(), e.run().driver(), e.run().mapIndex(),
                    e.mapNanos(), e.driverNanos())));
        }
        StringBuilder drivers = new StringBuilder(check.header(DriversCsv.HEADER, false)).append('\n');
        for (Journal.Finished f : finished) {
            drivers.append(check.rows(DriversCsv.row(f.spend())));
            timings.append(check.rows(TimingsCsv.doneRow(f.spend().replication(), f.spend().driver(), f.spend().mapsRun(),
                    f.driverNanos())));
        }
        OutputFile.writeString(folder.resolve(ResultsFolder.TIMINGS), timings.toString());
        OutputFile.writeString(folder.resolve(ResultsFolder.RUNS), runs.toString());
        OutputFile.writeString(folder.resolve(ResultsFolder.DRIVERS), drivers.toString());
    }
}
