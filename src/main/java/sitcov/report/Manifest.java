package sitcov.report;

import java.io.IOException;
import java.io.Reader;
import java.io.StringReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HexFormat;
import java.util.List;
import java.util.Map;
import java.util.Properties;
import java.util.TreeMap;
import sitcov.coverage.GridDefinition;
import sitcov.experiment.AnalysisPlan;
import sitcov.experiment.BudgetKind;
import sitcov.experiment.ExperimentConfig;
import sitcov.experiment.FaultyRuns;
import sitcov.experiment.Shard;
import sitcov.faults.FaultSet;

/**
 * {@code manifest.properties}: everything that fixes an experiment's results (the configuration,
 * sitcov's version, the grid and its hash), which shard the folder holds, whether it is complete,
 * and whether a wall-clock budget was interrupted. Nothing timed, so complete folders of the same
 * experiment have the same manifest. A results folder can be resumed or merged from it alone.
 */
public record Manifest(ExperimentConfig config, String version, Shard shard, boolean complete, boolean resumed) {
    private static final String HEADER = "# sitcov experiment manifest";

    public Manifest complete(boolean done) {
        return new Manifest(config, version, shard, done, resumed);
    }

    /** The same experiment, marked resumed when that changes its results (a wall-clock budget). */
    public Manifest resumedRun() {
        return new Manifest(config, version, shard, complete, resumed || config.budget() == BudgetKind.WALL_CLOCK);
    }

    public Manifest whole() {
        return new Manifest(config, version, Shard.WHOLE, complete, resumed);
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
        m.put("faults", FaultSet.format(c.faults()));
        m.put("budget", c.budget().key());
        m.put("candidate_limit", Integer.toString(c.candidateLimit()));
        m.put("faulty_runs", c.faultyRuns().key());
        m.put("grid", ResultsFolder.GRID);
        m.put("grid_sha256", sha256(c.grid().format()));
        m.putAll(c.analysis().properties());
        return m;
    }

    List<String> lines() {
        Map<String, String> m = new TreeMap<>(identity());
        m.put("complete", Boolean.toString(complete));
        if (!shard.isWhole()) {
            m.put("shard", shard.toString());
        }
        if (resumed) {
            m.put("resumed", "true");
        }
        List<String> rows = new ArrayList<>();
        rows.add(HEADER);
        m.forEach((k, v) -> rows.add(k + "=" + v));
        return rows;
    }

    /** Writes the manifest and the grid file beside it. */
    void write(Path folder) throws IOException {
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
        try (Reader r = new StringReader(Files.readString(file, StandardCharsets.UTF_8))) {
            p.load(r);
        } catch (NoSuchFileException e) {
            throw new IllegalArgumentException(folder + " is not a results folder: it has no " + ResultsFolder.MANIFEST);
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
                    FaultSet.parse(required(p, "faults")), BudgetKind.ofKey(required(p, "budget")), grid,
                    drivers, sweep, Integer.parseInt(required(p, "candidate_limit")),
                    // folders written before faulty runs could stop at their verdict ran them to the end
                    FaultyRuns.ofKey(p.getProperty("faulty_runs", FaultyRuns.TO_END.key())),
                    // folders written before the analysis was declared are judged by its defaults
                    AnalysisPlan.read(p::getProperty, drivers));
            Shard shard = p.containsKey("shard") ? Shard.parse(p.getProperty("shard")) : Shard.WHOLE;
            return new Manifest(config, required(p, "sitcov_version"), shard,
                    Boolean.parseBoolean(required(p, "complete")), Boolean.parseBoolean(p.getProperty("resumed", "false")));
        } catch (NoSuchFileException e) {
            throw new IllegalArgumentException(folder + " lacks " + e.getFile() + "; it is not a whole results folder");
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException(file + ": " + e.getMessage(), e);
        }
    }

    private static String required(Properties p, String key) {
        String v = p.getProperty(key);
        if (v == null) {
            throw new IllegalArgumentException("no '" + key + "='");
        }
        return v.strip();
    }

    static String sha256(String text) {
        try {
            return HexFormat.of().formatHex(MessageDigest.getInstance("SHA-256").digest(text.getBytes(StandardCharsets.UTF_8)));
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("every JDK has SHA-256", e);
        }
    }
}
