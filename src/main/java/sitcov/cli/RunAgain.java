package sitcov.cli;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import sitcov.experiment.CampaignConfig;
import sitcov.experiment.Shard;
import sitcov.results.CampaignManifest;
import sitcov.results.IoReason;
import sitcov.results.Manifest;
import sitcov.results.ResultsFolder;

/** {@code run --again DIR}, apart from {@link RunCommand} whose start it shares. */
final class RunAgain {
    private RunAgain() {
    }

    /**
     * {@code run --again DIR}: the experiment or campaign DIR's manifest describes (its shard too), run again
     * into a new folder; what a refused folder's message advises, since the preset it came from may lie anywhere.
     */
    static int run(RunCommand command, Options options, int threads, PrintStream out, PrintStream err)
            throws UsageException {
        if (!options.positional().isEmpty() || options.has("--resume") || options.has("--seed") || options.has("--shard")
                || options.has("--replications") || options.has("--controller") || options.has("--variants")) {
            throw new UsageException("run: --again DIR takes the experiment from DIR's manifest; give only --out, --threads, --record,"
                    + " --fork and --dry-run beside it.");
        }
        Path folder = Path.of(options.value("--again").get());
        boolean campaign = CampaignManifest.isCampaign(folder);
        if (!campaign && !Files.isRegularFile(folder.resolve(ResultsFolder.MANIFEST))) {
            throw new UsageException("run: --again " + Options.shown(folder) + " is not a results folder (it has no "
                    + ResultsFolder.MANIFEST + "); name the folder whose experiment to run again.");
        }
        CampaignConfig c;
        Shard campaignShard;
        Manifest manifest;
        try {
            CampaignManifest cm = campaign ? CampaignManifest.read(folder) : null;
            c = campaign ? cm.config() : null;
            campaignShard = campaign ? cm.shard() : Shard.WHOLE;
            manifest = campaign ? null : Manifest.read(folder);
        } catch (IOException e) {
            throw new UsageException("run: cannot read " + folder + ": " + IoReason.of(e, folder) + ".");
        } catch (IllegalArgumentException e) {
            throw new UsageException("run: --again " + folder + ": " + e.getMessage() + ".");
        }
        if (campaign) {
            return command.campaign(c, campaignShard, options, threads, out, err);
        }
        return command.start(manifest.config(), manifest.shard(), options, folder.resolve(ResultsFolder.MANIFEST).toString(),
                threads, out, err);
    }
}
