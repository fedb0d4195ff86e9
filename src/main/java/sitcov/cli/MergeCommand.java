package sitcov.cli;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Set;
import sitcov.analysis.Summary;
import sitcov.builtin.BuiltinCar;
import sitcov.report.CampaignMerger;
import sitcov.report.ShardMerger;
import sitcov.results.CampaignManifest;
import sitcov.results.IoReason;
import sitcov.results.Manifest;

/** {@code merge DIR... --out DIR}: the folders of shards 1/N … N/N into the folder the unsharded run would write. */
final class MergeCommand implements Command {
    @Override
    public String name() {
        return "merge";
    }

    @Override
    public String synopsis() {
        return "SHARD_DIR... --out DIR";
    }

    @Override
    public String summary() {
        return "combine the results folders of run --shard 1/N ... N/N into one, as the unsharded run would write it";
    }

    @Override
    public int run(List<String> args, PrintStream out, PrintStream err) throws UsageException {
        Options options = Options.parse(name(), args, Set.of("--out"), Set.of());
        if (options.positional().isEmpty()) {
            throw new UsageException("merge: name the shard folders, e.g. 'merge results/shard-1 results/shard-2 --out results/all'.");
        }
        Path target = Path.of(options.value("--out").orElseThrow(() -> new UsageException(
                "merge: say where the merged results go with --out DIR (a new or empty folder).")));
        if (Files.isRegularFile(target) || (Files.isDirectory(target) && !RunCommand.isEmpty(target))) {
            throw new UsageException("merge: --out " + target + " exists and is not an empty folder; name a new folder.");
        }
        List<Path> shards = options.positional().stream().map(Path::of).toList();
        for (Path s : shards) {
            if (!Files.isDirectory(s)) {
                throw new UsageException("merge: " + s + " is not a folder; name the results folders of run --shard.");
            }
        }
        if (sitcov.estimate.EstimateFolder.isEstimate(shards.get(0))) {
            return mergeEstimates(shards, target, out, err);
        }
        if (CampaignManifest.isCampaign(shards.get(0))) {
            return mergeCampaign(shards, target, out, err);
        }
        try {
            Summary summary = ShardMerger.merge(shards, target, RunCommand.execution(1), BuiltinCar.FACTORY);
            Manifest merged = Manifest.read(target);
            if (!merged.checked()) {
                err.println("sitcov: merge: " + Manifest.uncheckedWarning(target) + " (a shard was written before checks).");
            }
            SummaryTable.print(out, merged.config(), summary);
            VerdictPrinter.print(out, target);
        } catch (IllegalArgumentException | IllegalStateException e) {
            throw new UsageException("merge: " + e.getMessage() + ".");
        } catch (IOException e) {
            err.println("sitcov: merge: could not write " + target + ": " + IoReason.of(e, target) + ".");
            return ExitCode.FAILURE;
        }
        out.println("Merged " + shards.size() + " shards into " + target);
        return ExitCode.OK;
    }

    /** The shards of a campaign (experiments/README.md, "Campaigns: falsifying one version"): each target's merged, then the campaign's files. */
    private static int mergeCampaign(List<Path> shards, Path target, PrintStream out, PrintStream err) throws UsageException {
        try {
            CampaignMerger.merge(shards, target, RunCommand.execution(1), BuiltinCar.FACTORY);
        } catch (IllegalArgumentException | IllegalStateException e) {
            throw new UsageException("merge: " + e.getMessage() + ".");
        } catch (IOException e) {
            err.println("sitcov: merge: could not write " + target + ": " + IoReason.of(e, target) + ".");
            return ExitCode.FAILURE;
        }
        VerdictPrinter.print(out, target);
        out.println("Merged " + shards.size() + " shards into " + target);
        return ExitCode.OK;
    }

    /** The shards of an estimate (experiments/estimate.md): their samples joined, the estimates made again. */
    private static int mergeEstimates(List<Path> shards, Path target, PrintStream out, PrintStream err) throws UsageException {
        try {
            sitcov.estimate.EstimateFolder.merge(shards, target).text().forEach(out::println);
            if (!sitcov.estimate.EstimateFolder.attested(target)) {
                err.println("sitcov: merge: warning: a shard's manifest keeps no digest of its samples (it was written"
                        + " before sitcov kept one), so a hand edit to them cannot be detected; " + target
                        + " is left without digests too. For an estimate that is checked, run it again.");
            }
        } catch (IllegalArgumentException e) {
            throw new UsageException("merge: " + e.getMessage() + ".");
        } catch (IOException e) {
            err.println("sitcov: merge: could not write " + target + ": " + IoReason.of(e, target) + ".");
            return ExitCode.FAILURE;
        }
        out.println();
        out.println("Merged " + shards.size() + " shards into " + target);
        return ExitCode.OK;
    }
}
