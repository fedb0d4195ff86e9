package sitcov.cli;

import java.io.IOException;
import java.io.PrintStream;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import sitcov.builtin.BuiltinCar;
import sitcov.drivers.Drivers;
import sitcov.experiment.CampaignConfig;
import sitcov.experiment.CampaignTarget;
import sitcov.experiment.ExperimentConfig;
import sitcov.experiment.ExperimentRunner;
import sitcov.experiment.Shard;
import sitcov.report.CampaignFinisher;
import sitcov.report.ResultsRecorder;
import sitcov.results.CampaignManifest;
import sitcov.results.FolderLock;
import sitcov.results.IoReason;
import sitcov.results.Manifest;
import sitcov.results.ResultsFolder;

/**
 * {@code run PRESET} for a campaign (experiments/README.md, "Campaigns: falsifying one version"): each target's trials
 * run as an ordinary experiment into its own sub-folder (streamed, resumable), one target after another,
 * then the campaign's own files are written from the sub-folders. {@code run --resume DIR} takes up a
 * killed campaign where it stopped: finished targets are kept, the interrupted one is resumed. With
 * {@code --shard K/N} every target's sub-folder holds that shard of its trials, and {@code merge} writes the
 * campaign's files once the shards are together.
 */
final class CampaignRun {
    private final Drivers drivers;
    private final int threads;
    private final boolean fork;
    private final PrintStream out;
    private final PrintStream err;

    CampaignRun(Drivers drivers, int threads, boolean fork, PrintStream out, PrintStream err) {
        this.fork = fork;
        this.drivers = drivers;
        this.threads = threads;
        this.out = out;
        this.err = err;
    }

    /** What a campaign does, as its first line says it. */
    static String plan(CampaignConfig c, Shard shard, int threads) {
        int n = c.targets().size();
        return "run: " + c.name() + (shard.isWhole() ? "" : " shard " + shard) + ": campaign of " + n + " " + c.noun()
                + (n == 1 ? "" : "s") + ", " + c.trials() + " trials per driver and " + c.noun() + ", at most "
                + c.tickBudget() + " ticks a trial, drivers " + String.join(", ", c.drivers()) + ", on " + threads
                + " threads";
    }

    int start(CampaignConfig c, Shard shard, Path folder) throws UsageException {
        FolderLock lock;
        try {
            Files.createDirectories(folder);
            lock = FolderLock.claim(folder);
        } catch (IOException e) {
            throw new UsageException("run: cannot create the results folder " + folder + ": " + IoReason.of(e, folder)
                    + "; choose a writable --out.");
        } catch (IllegalStateException e) {
            throw new UsageException("run: " + e.getMessage() + ".");
        }
        CampaignManifest manifest = new CampaignManifest(c, Version.current(), shard, false);
        try {
            if (!ResultsFolder.holdsNothing(folder)) {
                lock.close();
                throw new UsageException("run: " + folder + " holds files already; results never overwrite earlier ones:"
                        + " name a new folder with --out.");
            }
            manifest.write(folder);
        } catch (IOException e) {
            close(lock);
            throw new UsageException("run: cannot write into " + folder + ": " + IoReason.of(e, folder) + ".");
        }
        return execute(manifest, folder, lock, "");
    }

    int resume(Path folder) throws UsageException {
        CampaignManifest manifest;
        FolderLock lock;
        try {
            manifest = CampaignManifest.read(folder);
            if (manifest.complete()) {
                throw new UsageException("run: " + folder + " is complete already; there is nothing to resume.");
            }
            if (!manifest.version().equals(Version.current())) {
                throw new UsageException("run: " + folder + " was written by sitcov " + manifest.version() + ", this is "
                        + Version.current() + "; resume it with that version, or start the preset afresh.");
            }
            if (!manifest.checked()) {
                err.println("sitcov: run: " + CampaignManifest.uncheckedWarning(folder) + ".");
            }
            lock = FolderLock.claim(folder);
            // what a kill while the campaign's own files were written left
            ResultsFolder.sweepTemporaries(folder);
        } catch (IOException e) {
            throw new UsageException("run: cannot resume " + folder + ": " + IoReason.of(e, folder) + ".");
        } catch (IllegalArgumentException | IllegalStateException e) {
            throw new UsageException("run: cannot resume " + folder + ": " + e.getMessage() + ".");
        }
        return execute(manifest, folder, lock, " (resumed)");
    }

    private int execute(CampaignManifest manifest, Path folder, FolderLock lock, String note) throws UsageException {
        CampaignConfig c = manifest.config();
        err.println(plan(c, manifest.shard(), threads) + ", into " + folder + note);
        long start = System.nanoTime();
        try {
            int n = 0;
            for (CampaignTarget f : c.targets()) {
                n++;
                int code = runTarget(manifest, f, folder.resolve(f.folder()), n);
                if (code != ExitCode.OK) {
                    return code;
                }
            }
            CampaignFinisher.finish(folder, manifest);
        } catch (IOException e) {
            err.println("sitcov: run: could not complete the campaign in " + folder + ": " + IoReason.of(e, folder)
                    + "; continue with 'run --resume " + folder + "'.");
            return ExitCode.FAILURE;
        } catch (IllegalArgumentException e) {
            throw new UsageException("run: " + e.getMessage() + ".");
        } finally {
            close(lock);
        }
        VerdictPrinter.print(out, folder);
        out.println("Results in " + folder + " (" + Math.round((System.nanoTime() - start) / 1e9) + " s on " + threads
                + (threads == 1 ? " thread)" : " threads)"));
        if (manifest.shard().isWhole()) {
            out.println("The report: " + folder.resolve(ResultsFolder.CAMPAIGN_PAGE)
                    + " (the verdict, the tables and the survival curves on one page; open it in a browser)");
        } else {
            out.println("Shard " + manifest.shard() + " of the campaign's trials: its tables and verdict are written by"
                    + " 'merge SHARD_DIR... --out DIR' once all " + manifest.shard().n() + " shards are done.");
        }
        return ExitCode.OK;
    }

    /** The trials of one target, into {@code sub}: skipped when complete, resumed when a kill interrupted them. */
    private int runTarget(CampaignManifest campaign, CampaignTarget f, Path sub, int n) throws IOException, UsageException {
        CampaignConfig c = campaign.config();
        Shard shard = campaign.shard();
        if (ResultsRecorder.isComplete(sub)) {
            CampaignFinisher.check(Manifest.read(sub), campaign, f, sub);
            return ExitCode.OK;
        }
        ExperimentConfig config = c.trialsOf(f);
        Map<String, String> execution = RunCommand.execution(threads);
        ResultsRecorder recorder;
        try {
            if (Files.isRegularFile(sub.resolve(ResultsFolder.MANIFEST))) {
                Manifest m = Manifest.read(sub);
                CampaignFinisher.check(m, campaign, f, sub);
                recorder = ResultsRecorder.resume(sub, m, execution, System::nanoTime, BuiltinCar.FACTORY);
            } else {
                recorder = ResultsRecorder.create(sub, new Manifest(config, Version.current(), shard, false, false),
                        execution, System::nanoTime, BuiltinCar.FACTORY);
            }
        } catch (IllegalStateException e) {
            throw new UsageException("run: " + e.getMessage() + ".");
        }
        Controllers.Opened controllers;
        try {
            Controllers.Opened opened = Controllers.open(config, sub);
            controllers = fork ? opened : opened.unforked();
        } catch (UsageException e) {
            recorder.close();
            throw e;
        }
        ProgressListener progress = new ProgressListener(err, err == System.err && System.console() != null,
                System::nanoTime);
        ExperimentRunner runner = new ExperimentRunner(config, drivers, shard, recorder.journal(), threads,
                System::nanoTime, List.of(recorder, progress), controllers.reference(), controllers.variants());
        err.println("run: " + f.column() + " " + f.key() + " (" + n + " of " + c.targets().size() + "), into " + sub);
        try (controllers) {
            runner.run();
        } catch (FolderLock.Lost e) {
            err.println("sitcov: run: " + e.getMessage() + "; it stopped there: run the preset again.");
            return ExitCode.FAILURE;
        } catch (IllegalStateException | UncheckedIOException e) {
            err.println("sitcov: run: " + e.getMessage());
            err.println("sitcov: run: what was judged is kept in " + sub + "; continue with 'run --resume "
                    + sub.getParent() + "'.");
            return ExitCode.FAILURE;
        } finally {
            recorder.close();
        }
        return ExitCode.OK;
    }

    private static void close(FolderLock lock) {
        try {
            lock.close();
        } catch (IOException e) {
            // the lock goes with the process anyway
        }
    }
}
