package sitcov.report;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import sitcov.analysis.Summary;
import sitcov.control.ControllerFactory;
import sitcov.experiment.DriverRun;
import sitcov.experiment.ExperimentConfig;
import sitcov.experiment.Journal;
import sitcov.experiment.MapRun;
import sitcov.experiment.PlannedReplication;
import sitcov.experiment.ReplicationResult;
import sitcov.figures.ExperimentFigures;
import sitcov.figures.SweepReport;
import sitcov.render.ReplayGallery;
import sitcov.results.FolderLock;
import sitcov.results.JournalFiles;
import sitcov.results.Manifest;
import sitcov.results.OutputFile;
import sitcov.results.ResultsFolder;
import sitcov.results.ResultsTables;

/**
 * Completes a results folder from its journal: the journal files in canonical order, then every
 * table and figure, then the manifest marked complete. A fresh run, a resumed one and a merge of
 * shards all end here, so they write the same files from the same journal.
 */
public final class ResultsFinisher {
    private ResultsFinisher() {
    }

    /** The replications of the manifest's shard, rebuilt from the journal; refused if any driver has not finished. */
    static List<ReplicationResult> results(Manifest manifest, Journal journal) {
        ExperimentConfig config = manifest.config();
        List<ReplicationResult> results = new ArrayList<>();
        for (PlannedReplication p : config.plan()) {
            if (!manifest.shard().includes(p.index())) {
                continue;
            }
            List<DriverRun> drivers = new ArrayList<>();
            for (String d : config.drivers()) {
                Journal.Finished f = journal.finished(p.index(), d).orElseThrow(() -> new IllegalArgumentException(
                        "driver " + d + " has not finished replication " + p.index()));
                List<MapRun> maps = journal.maps(p.index(), d).stream().map(Journal.Entry::run).toList();
                if (maps.size() != f.spend().mapsRun()) {
                    throw new IllegalArgumentException("driver " + d + " ran " + f.spend().mapsRun() + " maps in replication "
                            + p.index() + " but the journal holds " + maps.size());
                }
                drivers.add(new DriverRun(d, maps, f.spend()));
            }
            results.add(new ReplicationResult(p.index(), drivers));
        }
        return results;
    }

    /**
     * Writes everything a complete folder holds; returns the summary the tables were made from. The
     * replay pictures of a folder of the builtin car are runs {@code builtin} makes.
     */
    public static Summary finish(Path folder, Manifest manifest, Journal journal, Map<String, String> execution,
                                 ControllerFactory builtin) throws IOException {
        Summary summary = writeResults(folder, manifest, journal, builtin);
        writeExecution(folder, execution);
        manifest.complete(true).write(folder);
        return summary;
    }

    /**
     * Writes a complete folder's tables, statistics and figures again from its journal, as this
     * version of sitcov makes them; the journal, manifest and record of execution stay as they are.
     * Holds the folder's lock meanwhile, and sweeps the temporary files a killed report left.
     *
     * @throws IllegalStateException when a run holds the folder
     * @throws IllegalArgumentException when the folder is incomplete or was changed by hand
     */
    public static Summary report(Path folder, ControllerFactory builtin) throws IOException {
        Manifest manifest = Manifest.read(folder);
        if (!manifest.complete()) {
            throw new IllegalArgumentException(folder + " is not complete; finish it with 'run --resume " + folder + "'");
        }
        try (FolderLock lock = FolderLock.claim(folder)) {
            ResultsFolder.sweepTemporaries(folder);
            return writeResults(folder, manifest, JournalFiles.read(folder, manifest), builtin);
        }
    }

    private static Summary writeResults(Path folder, Manifest manifest, Journal journal, ControllerFactory builtin)
            throws IOException {
        ExperimentConfig config = manifest.config();
        List<ReplicationResult> results = results(manifest, journal);
        JournalFiles.write(folder, manifest, journal);
        Summary summary = new Summary(config, results);
        if (config.budget() == sitcov.experiment.BudgetKind.FIXED_TICKS) {
            // one fault's trials of a campaign: the campaign's folder analyses them with the other faults'
            // (CampaignFinisher); the suites' tables would compare drivers on maps they were not meant to share
            return summary;
        } else if (config.isSweep()) {
            SweepReport.write(config, summary, folder);
        } else {
            ResultsTables tables = new ResultsTables(config, summary);
            OutputFile.writeLines(folder.resolve(ResultsFolder.SUMMARY), tables.summary());
            OutputFile.writeLines(folder.resolve(ResultsFolder.TABLE2), tables.table2());
            OutputFile.writeLines(folder.resolve(ResultsFolder.COVERAGE_CURVE), tables.curve());
            ExperimentFigures.writeAll(config, summary, journal, folder);
            AnalysisFiles.write(config, summary, folder);
            List<MapRun> inOrder = JournalFiles.inOrder(config, journal).stream().map(Journal.Entry::run).toList();
            ReportPictures pictures = ReportPictures.of(config.variants(), inOrder);
            ReplayGallery.write(folder, config, pictures.drawn(), builtin);
            OutputFile.writeString(folder.resolve(ResultsFolder.REPORT), HtmlReport.html(folder, config, inOrder, pictures));
        }
        return summary;
    }

    static void writeExecution(Path folder, Map<String, String> execution) throws IOException {
        List<String> rows = new ArrayList<>();
        rows.add("# how this results folder was produced (not part of the results)");
        new TreeMap<>(execution).forEach((k, v) -> rows.add(k + "=" + v));
        OutputFile.writeLines(folder.resolve(ResultsFolder.EXECUTION), rows);
    }
}
