package sitcov.report;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import sitcov.analysis.CampaignAnalysis;
import sitcov.analysis.CampaignTrial;
import sitcov.experiment.CampaignConfig;
import sitcov.experiment.DriverRun;
import sitcov.experiment.Journal;
import sitcov.experiment.ReplicationResult;
import sitcov.experiment.SeedPlan;
import sitcov.experiment.CampaignTarget;
import sitcov.figures.CampaignFigure;
import sitcov.results.CampaignCsv;
import sitcov.results.CampaignManifest;
import sitcov.results.FolderLock;
import sitcov.results.JournalFiles;
import sitcov.results.Manifest;
import sitcov.results.OutputFile;
import sitcov.results.ResultsFolder;
import sitcov.verdict.CampaignVerdict;
import sitcov.verdict.RequirementVerdict;

/**
 * Completes a campaign's results folder from its faults' sub-folders (experiments/README.md, "Campaigns: falsifying
 * one version"): campaign.csv and its other tables, the verdict, the figure and campaign.html. Only the
 * sub-folders' journals are read, so a run, a resumed run and a report write the same bytes.
 */
public final class CampaignFinisher {
    public static final String PAGE = ResultsFolder.CAMPAIGN_PAGE;

    private CampaignFinisher() {
    }

    /**
     * Writes every file of the campaign and marks its manifest complete. A shard's folder holds only its share
     * of the trials, which no analysis should be read from: it is marked complete, and its files are written
     * once the shards are merged.
     */
    public static void finish(Path folder, CampaignManifest manifest) throws IOException {
        if (manifest.shard().isWhole()) {
            // trials read back from a campaign.csv whose digest was never kept are written again as they were, unattested
            boolean attest = !keepsOnlyTrials(folder, manifest.config()) || manifest.trialsSha256().isPresent();
            CampaignAnalysis a = analyse(folder, manifest);
            List<String> trials = CampaignCsv.trials(a);
            OutputFile.writeLines(folder.resolve(CampaignCsv.TRIALS), trials);
            OutputFile.writeLines(folder.resolve(CampaignCsv.DRIVERS), CampaignCsv.drivers(a));
            OutputFile.writeLines(folder.resolve(CampaignCsv.STATS), CampaignCsv.stats(a));
            List<String> verdict = a.config().onRequirements() ? RequirementVerdict.lines(a) : CampaignVerdict.lines(a);
            OutputFile.writeLines(folder.resolve(ResultsFolder.VERDICT), verdict);
            CampaignFigure.write(a, folder);
            OutputFile.writeString(folder.resolve(PAGE), a.config().onRequirements() ? RequirementPage.html(a, verdict)
                    : CampaignPage.html(a, verdict));
            (attest ? manifest.completeWith(trials) : manifest.complete(true)).write(folder);
            return;
        }
        manifest.complete(true).write(folder);
    }

    /**
     * Writes a complete campaign's own files again from its sub-folders, holding its lock meanwhile.
     *
     * @throws IllegalArgumentException when the campaign is incomplete or a sub-folder was changed by hand
     * @throws IllegalStateException when a run holds the folder
     */
    public static void report(Path folder) throws IOException {
        CampaignManifest manifest = CampaignManifest.read(folder);
        if (!manifest.complete()) {
            throw new IllegalArgumentException(folder + " is not complete; finish it with 'run --resume " + folder + "'");
        }
        if (!manifest.shard().isWhole()) {
            throw new IllegalArgumentException(folder + " holds shard " + manifest.shard() + " of a campaign, whose"
                    + " report is written once all " + manifest.shard().n() + " shards are merged: 'merge SHARD_DIR... --out DIR'");
        }
        try (FolderLock lock = FolderLock.claim(folder)) {
            ResultsFolder.sweepTemporaries(folder);
            finish(folder, manifest);
        }
    }

    /**
     * The campaign's trials, read from each target's complete sub-folder, or from campaign.csv when the folder
     * {@linkplain #keepsOnlyTrials keeps only that}.
     *
     * @throws IllegalArgumentException when a sub-folder is missing, incomplete, changed by hand or of another campaign
     */
    public static CampaignAnalysis analyse(Path folder, CampaignManifest manifest) throws IOException {
        CampaignConfig c = manifest.config();
        if (keepsOnlyTrials(folder, c)) {
            Path file = folder.resolve(CampaignCsv.TRIALS);
            manifest.verifyTrials(folder, Files.readString(file));
            List<String> lines = Files.readAllLines(file);
            return CampaignAnalysis.of(c, CampaignCsv.readTrials(c, file, lines));
        }
        List<CampaignTrial> trials = new ArrayList<>();
        for (CampaignTarget f : c.targets()) {
            Path sub = folder.resolve(f.folder());
            Manifest m = Manifest.read(sub);
            check(m, manifest, f, sub);
            if (!m.complete()) {
                throw new IllegalArgumentException(sub + " is not complete; finish the campaign with 'run --resume " + folder
                        + "'");
            }
            Journal journal = JournalFiles.read(sub, m);
            for (ReplicationResult r : ResultsFinisher.results(m, journal)) {
                for (DriverRun d : r.drivers()) {
                    trials.add(CampaignTrial.of(f, r.replication(), m.config().masterSeed(),
                            SeedPlan.replicationLabel(r.replication()), c.tickBudget(), d));
                }
            }
        }
        trials.sort(Comparator.comparingInt((CampaignTrial t) -> t.target().order()).thenComparingInt(t -> c.drivers().indexOf(t.driver()))
                .thenComparingInt(CampaignTrial::trial));
        return CampaignAnalysis.of(c, trials);
    }

    /**
     * Whether the folder keeps campaign.csv but none of its targets' sub-folders, as a published campaign does (the
     * sub-folders hold every map's runs and situations, hundreds of MB): every statistic is computed from the
     * trials, which campaign.csv holds whole, so its other files can still be written again.
     */
    public static boolean keepsOnlyTrials(Path folder, CampaignConfig c) {
        return Files.isRegularFile(folder.resolve(CampaignCsv.TRIALS))
                && c.targets().stream().noneMatch(t -> Files.exists(folder.resolve(t.folder())));
    }

    /** Refuses a sub-folder that is not the experiment (and shard) the campaign implies for {@code target}. */
    public static void check(Manifest m, CampaignManifest campaign, CampaignTarget target, Path sub) {
        Manifest expected = new Manifest(campaign.config().trialsOf(target), m.version(), campaign.shard(), m.complete(),
                m.resumed());
        if (!expected.identity().equals(m.identity()) || !m.shard().equals(campaign.shard())) {
            throw new IllegalArgumentException(sub + " holds another experiment than this campaign's trials of "
                    + target.column() + " " + target.key() + " (its manifest differs); put back the folder the campaign"
                    + " wrote, or run the campaign again into a new folder: " + Manifest.again(campaignFolder(sub)));
        }
    }

    /** The campaign folder a target's sub-folder lies in, as the user named it. */
    private static Path campaignFolder(Path sub) {
        Path parent = sub.normalize().getParent();
        return parent != null ? parent : Path.of(".");
    }
}
