package sitcov.results;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.regex.Pattern;
import java.util.stream.Stream;

/**
 * The files of an experiment's results folder: the one place their names are written down. The
 * journal files grow while the experiment runs; the rest are written when it ends. Under the ticks
 * budget every file but the {@link #TIMED} ones is the same byte for byte however the run was
 * split, interrupted or threaded.
 */
public final class ResultsFolder {
    /** One row per simulated run, one block of rows per judged map. */
    public static final String RUNS = "runs.csv";
    /** What each driver spent in each replication, and why it stopped. */
    public static final String DRIVERS = "drivers.csv";
    /** Wall time per judged map and per driver: the only record of time, kept apart. */
    public static final String TIMINGS = "timings.csv";
    /** The experiment's exact configuration, sitcov's version, and whether the folder is complete. */
    public static final String MANIFEST = "manifest.properties";
    /** How this folder was produced: threads, wall time, JDK, resumes, shards. */
    public static final String EXECUTION = "execution.properties";
    /** The coverage grid definition the experiment used. */
    public static final String GRID = "grid.txt";
    /** Situation files of maps that drivers built (named in runs.csv as situation:NAME). */
    public static final String SITUATIONS = "situations";
    /** The commands of every run the folder lists as a failure or a finding (RUN.jsonl.gz; sitcov.recording). */
    public static final String RECORDINGS = "recordings";
    /** Replays of the maps that found each fault, one picture a fault (fault-ID.png). */
    public static final String REPLAYS = "replays";
    public static final String SUMMARY = "summary.csv";
    public static final String TABLE2 = "table2.csv";
    public static final String COVERAGE_CURVE = "coverage-curve.csv";
    public static final String FIG2 = "fig2-faults-per-map.png";
    public static final String FIG3 = "fig3-coverage.png";
    public static final String FIG3_TIME = "fig3-coverage-time.png";
    /** Every pair of drivers: per measure and per fault, the difference with its uncertainty. */
    public static final String STATS = "stats.csv";
    /** The comparison in a few plain sentences, as {@code run} prints it at the end. */
    public static final String VERDICT = "verdict.txt";
    /** Per replication, driver and fault: the ticks and candidates spent when the fault was first found. */
    public static final String DISCOVERY = "discovery.csv";
    /** Per coverage cell: distinct maps, and how many found each fault. */
    public static final String CELL_FAULTS = "cell-faults.csv";
    /** Per fault: how much of the variation in detection the cell explains, against chance. */
    public static final String UNIFORMITY = "uniformity.csv";
    /** The maps on which the fault-free car failed on its own, with the command that replays each. */
    public static final String OWN_FAILURES = "own-failures.csv";
    /** Everything on one self-contained page: verdict, tables, figures, grid, the maps that found each fault. */
    public static final String REPORT = "report.html";
    private static final String FOREST_PLOT = "fig-faults-odds-ratios";
    public static final String FIG_MEASURES = "fig-measures-by-driver.png";
    public static final String FIG_DISCOVERY = "fig-faults-found-vs-ticks.png";
    public static final String SWEEP = "sweep.csv";
    public static final String FIG4 = "fig4-faults-vs-coverage.png";

    /** Held by the run writing the folder; gone when it ends (a killed run leaves it, unlocked). */
    public static final String LOCK = ".sitcov.lock";

    /** A campaign's own files, at the top of its folder (experiments/README.md, "Campaigns: falsifying one version"). */
    public static final String CAMPAIGN_MANIFEST = "campaign.properties";
    public static final String CAMPAIGN_TRIALS = "campaign.csv";
    public static final String CAMPAIGN_DRIVERS = "campaign-drivers.csv";
    public static final String CAMPAIGN_STATS = "campaign-stats.csv";
    public static final String CAMPAIGN_FIGURE = "fig-campaign-survival.png";
    public static final String CAMPAIGN_PAGE = "campaign.html";

    /** Files whose content depends on how fast the machine was. */
    public static final List<String> TIMED = List.of(TIMINGS, EXECUTION, FIG3_TIME);

    /** Every file name sitcov writes at the top of a results folder. */
    private static final List<String> NAMES = List.of(RUNS, DRIVERS, TIMINGS, MANIFEST, EXECUTION, GRID, SUMMARY, TABLE2,
            COVERAGE_CURVE, FIG2, FIG3, FIG3_TIME, STATS, VERDICT, DISCOVERY, CELL_FAULTS, UNIFORMITY, OWN_FAILURES, REPORT,
            FIG_MEASURES, FIG_DISCOVERY, SWEEP, FIG4, CAMPAIGN_MANIFEST, CAMPAIGN_TRIALS, CAMPAIGN_DRIVERS, CAMPAIGN_STATS,
            CAMPAIGN_FIGURE, CAMPAIGN_PAGE);

    /**
     * The temporary files {@link OutputFile} names ({@code .NAME<digits>.tmp}) for the files sitcov
     * writes: at the top, in situations/, replays/ and recordings/. A kill leaves them; nothing else matches.
     */
    private static final Pattern TOP_TEMP = Pattern.compile("\\.(" + String.join("|", NAMES.stream().map(Pattern::quote)
            .toList()) + "|" + Pattern.quote(FOREST_PLOT) + "-\\d+-[A-Za-z0-9._-]+-vs-[A-Za-z0-9._-]+\\.png)\\d+\\.tmp");
    private static final Pattern SITUATION_TEMP = Pattern.compile("\\.[A-Za-z0-9][A-Za-z0-9._-]*\\.situation\\d+\\.tmp");
    private static final Pattern REPLAY_TEMP = Pattern.compile("\\.fault-\\d+\\.png\\d+\\.tmp");
    private static final Pattern RECORDING_TEMP = Pattern.compile("\\.r\\d+-[A-Za-z0-9._-]+\\.jsonl\\.gz\\d+\\.tmp");

    private ResultsFolder() {
    }

    /**
     * Deletes the temporary files a killed run left in {@code folder} (only those sitcov names, never
     * another file). Call it only while holding the folder's {@link FolderLock}: a live run's
     * temporary files are not stale.
     */
    public static void sweepTemporaries(Path folder) throws IOException {
        sweep(folder, TOP_TEMP);
        sweep(folder.resolve(SITUATIONS), SITUATION_TEMP);
        sweep(folder.resolve(REPLAYS), REPLAY_TEMP);
        sweep(folder.resolve(RECORDINGS), RECORDING_TEMP);
    }

    private static void sweep(Path dir, Pattern temp) throws IOException {
        if (!Files.isDirectory(dir)) {
            return;
        }
        try (Stream<Path> files = Files.list(dir)) {
            for (Path f : files.filter(f -> temp.matcher(f.getFileName().toString()).matches()).toList()) {
                if (Files.isRegularFile(f, java.nio.file.LinkOption.NOFOLLOW_LINKS)) {
                    Files.deleteIfExists(f);
                }
            }
        }
    }

    /**
     * Whether {@code folder} holds nothing but what a run killed before it wrote anything leaves: its
     * lock file and sitcov's temporary files. Such a folder is taken as empty by {@code run --out}.
     */
    public static boolean holdsNothing(Path folder) throws IOException {
        try (Stream<Path> files = Files.list(folder)) {
            return files.map(f -> f.getFileName().toString())
                    .allMatch(n -> n.equals(LOCK) || TOP_TEMP.matcher(n).matches());
        }
    }

    /**
     * The forest plot of one pair of drivers' per-fault odds ratios, as in
     * {@code fig-faults-odds-ratios-01-coverage-filter-vs-random.png}: pairs are numbered from 1, the primary
     * question's pair first, so that name order is the order of the pairs (see {@code StatsFigures}).
     */
    public static String forestPlot(int number, String driverA, String driverB) {
        return String.format(Locale.ROOT, "%s-%02d-%s-vs-%s.png", FOREST_PLOT, number, fileSafe(driverA), fileSafe(driverB));
    }

    /** Whether a file of the folder is a forest plot, of this naming or of the single one older versions drew. */
    public static boolean isForestPlot(String fileName) {
        return fileName.startsWith(FOREST_PLOT) && fileName.endsWith(".png");
    }

    /** A driver's name as part of a file name: presets name drivers in letters and hyphens, anything else becomes _. */
    private static String fileSafe(String name) {
        return name.replaceAll("[^A-Za-z0-9._-]", "_");
    }

    public static Path situation(Path folder, String name) {
        return folder.resolve(SITUATIONS).resolve(name + ".situation");
    }
}
