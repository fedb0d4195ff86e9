package sitcov.results;

import java.io.IOException;
import java.io.Reader;
import java.io.StringReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.Arrays;
import java.util.HexFormat;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Properties;
import java.util.TreeMap;
import sitcov.coverage.GridDefinition;
import sitcov.experiment.AnalysisPlan;
import sitcov.experiment.BudgetKind;
import sitcov.experiment.ExperimentConfig;
import sitcov.experiment.Shard;
import sitcov.faults.FaultSet;
import sitcov.judge.VariantList;
import sitcov.judge.FaultyRuns;
import sitcov.judge.Requirement;

/**
 * {@code manifest.properties}: everything that fixes an experiment's results (the configuration,
 * sitcov's version, the grid and its hash), which shard the folder holds, whether it is complete,
 * and whether a wall-clock budget was interrupted. Nothing timed, so complete folders of the same
 * experiment have the same manifest. A results folder can be resumed or merged from it alone.
 *
 * <p>{@code checks} holds a CRC-32 of every other line but {@code complete} (the one line the tool
 * itself flips, and whose edits the journal exposes), so a hand edit is refused naming its key
 * (experiments/README.md, "The results folder"). {@code checked} is false for a folder written before checks:
 * it is read, and written again, without them.
 */
public record Manifest(ExperimentConfig config, String version, Shard shard, boolean complete, boolean resumed,
                       boolean checked, boolean recordsAll) {
    private static final String HEADER = "# sitcov experiment manifest";
    static final String CHECKS = ManifestChecks.CHECKS;
    private static final String COMPLETE = ManifestChecks.COMPLETE;
    /** The key, present only as {@code recordings=all}, of a folder that keeps every run's recording ({@code --record all}). */
    private static final String RECORDINGS = "recordings";
    private static final String ALL = "all";

    /** A manifest with checks, as every folder is written now, recording failures and findings only. */
    public Manifest(ExperimentConfig config, String version, Shard shard, boolean complete, boolean resumed) {
        this(config, version, shard, complete, resumed, true, false);
    }

    /** A manifest recording failures and findings only. */
    public Manifest(ExperimentConfig config, String version, Shard shard, boolean complete, boolean resumed,
                    boolean checked) {
        this(config, version, shard, complete, resumed, checked, false);
    }

    public Manifest complete(boolean done) {
        return new Manifest(config, version, shard, done, resumed, checked, recordsAll);
    }

    /** The same experiment, marked resumed when that changes its results (a wall-clock budget). */
    public Manifest resumedRun() {
        return new Manifest(config, version, shard, complete, resumed || config.budget() == BudgetKind.WALL_CLOCK, checked,
                recordsAll);
    }

    public Manifest whole() {
        return new Manifest(config, version, Shard.WHOLE, complete, resumed, checked, recordsAll);
    }

    /** The same experiment keeping the recordings of every run, passing ones too ({@code all}), or of failures and findings only. */
    public Manifest recordingAll(boolean all) {
        return new Manifest(config, version, shard, complete, resumed, checked, all);
    }

    /** What to say of a folder written before checks, which is read as it is. */
    public static String uncheckedWarning(Path folder) {
        return "warning: " + folder + " was written before sitcov checked its results folders, so a hand edit to it"
                + " cannot be detected; for a folder that is checked, " + again(folder);
    }

    /** SHA-256 of the identity's lines: what keys the journal's checks to this experiment. */
    String experimentDigest() {
        StringBuilder text = new StringBuilder();
        identity().forEach((k, v) -> text.append(k).append('=').append(v).append('\n'));
        return sha256(text.toString());
    }

    /**
     * The command that runs the experiment of {@code folder} again into a new folder, as it would be typed
     * where {@code folder} names it. It names the folder rather than the preset, which may lie anywhere; a
     * campaign's sub-folder is run again with its campaign.
     */
    String rerun(Path folder) {
        Path f = folder.normalize();
        Path parent = f.getParent() != null ? f.getParent() : Path.of(f.toString().isEmpty() ? ".." : ".");
        Path name = folder.toAbsolutePath().normalize().getFileName();
        boolean sub = name != null && CampaignManifest.isCampaign(parent) && config.name().endsWith("-" + name);
        return again(sub ? parent : f) + (recordsAll ? " --record all" : "");
    }

    /** The command that runs the experiment or campaign of {@code folder} again into a new folder. */
    public static String again(Path folder) {
        return "run --again " + ShellWord.of(folder.toString().isEmpty() ? "." : folder.toString());
    }

    /** The keys that say which experiment this is: folders to merge must agree on all of them. */
    public Map<String, String> identity() {
        Map<String, String> m = new TreeMap<>();
        ExperimentConfig c = config;
        m.put("preset", c.name());
        m.put("sitcov_version", version);
        m.put("master_seed", Long.toString(c.masterSeed()));
        m.put("drivers", String.join(",", c.drivers()));
        m.put("candidates", Integer.toString(c.candidates()));
        m.put("replications", Integer.toString(c.replications()));
        if (c.isSweep()) {
            m.put("sweep", String.join(",", c.sweep().stream().map(String::valueOf).toList()));
        }
        if (!c.variants().isEmpty() && c.onlySeeded()) {
            m.put("faults", FaultSet.format(c.faults()));
        } else {
            m.put("variants", VariantList.format(c.variants()));
        }
        m.put("budget", c.budget().key());
        m.put("candidate_limit", Integer.toString(c.candidateLimit()));
        if (c.tickBudget() > 0) {
            m.put("tick_budget", Long.toString(c.tickBudget()));
        }
        c.requirement().ifPresent(r -> m.put("requirement", r.key()));
        m.put("faulty_runs", c.faultyRuns().key());
        if (!c.controller().equals(ExperimentConfig.BUILTIN)) {
            m.put("controller", c.controller());
        }
        m.put("grid", ResultsFolder.GRID);
        m.put("grid_sha256", sha256(c.grid().format()));
        m.putAll(c.analysis().properties());
        return m;
    }

    List<String> lines() {
        Map<String, String> m = new TreeMap<>(identity());
        if (!shard.isWhole()) {
            m.put("shard", shard.toString());
        }
        if (resumed) {
            m.put("resumed", "true");
        }
        if (recordsAll) {
            // not of the identity: which runs are recorded changes no result, nor the checks of the journal's rows;
            // absent otherwise, so that a folder recording failures only keeps the manifest it always had
            m.put(RECORDINGS, ALL);
        }
        return ManifestChecks.lines(HEADER, m, checked, complete);
    }

    /** Writes the manifest and the grid file beside it. */
    public void write(Path folder) throws IOException {
        OutputFile.writeLines(folder.resolve(ResultsFolder.GRID), Arrays.asList(config.grid().format().split("\n")));
        OutputFile.writeLines(folder.resolve(ResultsFolder.MANIFEST), lines());
    }

    /**
     * Reads a results folder's manifest and grid.
     *
     * @throws IllegalArgumentException naming the folder and what is missing or wrong
     */
    public static Manifest read(Path folder) throws IOException {
        Path file = folder.resolve(ResultsFolder.MANIFEST);
        Properties p = new Properties();
        String text;
        try {
            text = Files.readString(file, StandardCharsets.UTF_8);
        } catch (NoSuchFileException e) {
            throw new IllegalArgumentException(folder + " is not a results folder: it has no " + ResultsFolder.MANIFEST);
        }
        try (Reader r = new StringReader(text)) {
            p.load(r);
        }
        if (p.containsKey(CHECKS)) {
            ManifestChecks.verify(text, file, "put the manifest back as it was, or run the experiment again into a new folder");
        }
        try {
            GridDefinition grid = GridDefinition.read(folder.resolve(ResultsFolder.GRID));
            if (!sha256(grid.format()).equals(required(p, "grid_sha256"))) {
                throw new IllegalArgumentException(ResultsFolder.GRID + " does not match grid_sha256: the grid was edited");
            }
            String sweepText = p.getProperty("sweep", "");
            List<Integer> sweep = sweepText.isBlank() ? List.of()
                    : Arrays.stream(sweepText.split(",")).map(s -> Integer.parseInt(s.strip())).toList();
            List<String> drivers = List.of(required(p, "drivers").split(","));
            ExperimentConfig config = new ExperimentConfig(required(p, "preset"), Long.parseLong(required(p, "master_seed")),
                    Integer.parseInt(required(p, "candidates")), Integer.parseInt(required(p, "replications")),
                    p.containsKey("variants") ? VariantList.parse(p.getProperty("variants"))
                            : ExperimentConfig.seeded(FaultSet.parse(required(p, "faults"))),
                    BudgetKind.ofKey(required(p, "budget")), grid,
                    drivers, sweep, Integer.parseInt(required(p, "candidate_limit")),
                    // folders written before faulty runs could stop at their verdict ran them to the end
                    FaultyRuns.ofKey(p.getProperty("faulty_runs", FaultyRuns.TO_END.key())),
                    // folders written before the analysis was declared are judged by its defaults
                    AnalysisPlan.read(p::getProperty, drivers),
                    p.getProperty("controller", ExperimentConfig.BUILTIN),
                    Long.parseLong(p.getProperty("tick_budget", "0").strip()),
                    p.containsKey("requirement") ? Optional.of(Requirement.ofKey(p.getProperty("requirement")))
                            : Optional.empty());
            Shard shard = p.containsKey("shard") ? Shard.parse(p.getProperty("shard")) : Shard.WHOLE;
            return new Manifest(config, required(p, "sitcov_version"), shard,
                    Boolean.parseBoolean(required(p, COMPLETE)), Boolean.parseBoolean(p.getProperty("resumed", "false")),
                    p.containsKey(CHECKS), readRecordings(p));
        } catch (NoSuchFileException e) {
            throw new IllegalArgumentException(folder + " lacks " + e.getFile() + "; it is not a whole results folder");
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException(file + ": " + e.getMessage(), e);
        }
    }

    private static boolean readRecordings(Properties p) {
        String value = p.getProperty(RECORDINGS);
        if (value != null && !value.strip().equals(ALL)) {
            throw new IllegalArgumentException(RECORDINGS + "=" + value + " is not a setting sitcov writes (only "
                    + RECORDINGS + "=" + ALL + ")");
        }
        return value != null;
    }

    private static String required(Properties p, String key) {
        String v = p.getProperty(key);
        if (v == null) {
            throw new IllegalArgumentException("no '" + key + "='");
        }
        return v.strip();
    }

    /** The SHA-256 of {@code text}'s UTF-8 bytes, in hex: how sitcov's manifests name what a file held. */
    public static String sha256(String text) {
        try {
            return HexFormat.of().formatHex(MessageDigest.getInstance("SHA-256").digest(text.getBytes(StandardCharsets.UTF_8)));
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("every JDK has SHA-256", e);
        }
    }
}
