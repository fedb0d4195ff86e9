package sitcov.cli;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Set;
import sitcov.analysis.Summary;
import sitcov.builtin.BuiltinCar;
import sitcov.report.CampaignFinisher;
import sitcov.report.ResultsFinisher;
import sitcov.results.CampaignManifest;
import sitcov.results.Manifest;
import sitcov.results.ResultsFolder;

/**
 * {@code report DIR}: a complete results folder's tables, statistics, verdict and figures written
 * again from its journal, e.g. after an upgrade of sitcov brought new ones; nothing is simulated.
 */
final class ReportCommand implements Command {
    @Override
    public String name() {
        return "report";
    }

    @Override
    public String synopsis() {
        return "DIR";
    }

    @Override
    public String summary() {
        return "write a complete results folder's tables, statistics, verdict and figures again from its journal";
    }

    @Override
    public int run(List<String> args, PrintStream out, PrintStream err) throws UsageException {
        Options options = Options.parse(name(), args, Set.of(), Set.of());
        if (options.positional().size() != 1) {
            throw new UsageException("report: name one results folder, e.g. 'report target/results/smoke-seed1'.");
        }
        Path folder = Path.of(options.positional().get(0));
        boolean campaign = CampaignManifest.isCampaign(folder);
        if (!campaign && !Files.isRegularFile(folder.resolve(sitcov.results.ResultsFolder.MANIFEST))) {
            throw new UsageException("report: " + Options.shown(folder) + " is not a results folder (it has no "
                    + sitcov.results.ResultsFolder.MANIFEST + "); name the folder 'run' wrote.");
        }
        try {
            if (campaign) {
                // a campaign's own files, written again from its faults' sub-folders, or from campaign.csv where the
                // folder keeps only that (experiments/README.md, "Campaigns: falsifying one version")
                CampaignManifest manifest = CampaignManifest.read(folder);
                if (!manifest.checked()) {
                    err.println("sitcov: report: " + CampaignManifest.uncheckedWarning(folder) + ".");
                }
                if (manifest.complete() && CampaignFinisher.keepsOnlyTrials(folder, manifest.config())) {
                    out.println("report: " + folder + " keeps campaign.csv but not its sub-folders; every other file is"
                            + " computed again from the trials campaign.csv holds.");
                    if (manifest.trialsSha256().isEmpty()) {
                        err.println("sitcov: report: warning: " + folder.resolve(ResultsFolder.CAMPAIGN_TRIALS) + " was written before sitcov kept its digest, so a"
                                + " hand edit to it cannot be detected; for a campaign that is checked, "
                                + Manifest.again(folder) + ".");
                    }
                }
                CampaignFinisher.report(folder);
            } else {
                Manifest manifest = Manifest.read(folder);
                if (!manifest.checked()) {
                    err.println("sitcov: report: " + Manifest.uncheckedWarning(folder) + ".");
                }
                Summary summary = ResultsFinisher.report(folder, BuiltinCar.FACTORY);
                SummaryTable.print(out, manifest.config(), summary);
            }
            VerdictPrinter.print(out, folder);
        } catch (IllegalArgumentException | IllegalStateException e) {
            throw new UsageException("report: " + e.getMessage() + ".");
        } catch (IOException e) {
            err.println("sitcov: report: could not write into " + folder + ": " + e.getMessage());
            return ExitCode.FAILURE;
        }
        out.println("Results written again in " + folder);
        return ExitCode.OK;
    }
}
