package sitcov.results;

import java.io.IOException;
import java.io.StringReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.Properties;
import java.util.Set;
import java.util.TreeMap;
import sitcov.coverage.GridDefinition;
import java.util.stream.Stream;
import sitcov.experiment.CampaignConfig;
import sitcov.experiment.CampaignTarget;
import sitcov.experiment.ExperimentConfig;
import sitcov.experiment.Shard;
import sitcov.faults.FaultSet;
import sitcov.judge.FaultyRuns;
import sitcov.judge.Requirement;
import sitcov.judge.Variant;
import sitcov.judge.VariantList;

/**
 * {@code campaign.properties}: what fixes a campaign's results folder (experiments/README.md, "Campaigns: falsifying
 * one version"), which shard of its trials it holds, and whether it is complete. Each target's sub-folder has its own
 * manifest, checked against the one this one implies, so a campaign folder is resumed, reported or merged from it alone.
 */
public record CampaignManifest(CampaignConfig config, String version, Shard shard, boolean complete) {
    public static final String FILE = ResultsFolder.CAMPAIGN_MANIFEST;
    private static final String HEADER = "# sitcov campaign manifest";

    /** The manifest of a whole campaign. */
    public CampaignManifest(CampaignConfig config, String version, boolean complete) {
        this(config, version, Shard.WHOLE, complete);
    }

    /** Whether {@code other} is a folder of the same campaign, whatever shard each holds and whether it is complete. */
    public boolean sameCampaign(CampaignManifest other) {
        return whole().complete(false).lines().equals(other.whole().complete(false).lines());
    }

    /** The same campaign, whole: what merging its shards makes. */
    public CampaignManifest whole() {
        return new CampaignManifest(config, version, Shard.WHOLE, complete);
    }

    /** Whether {@code folder} holds a campaign (rather than one experiment). */
    public static boolean isCampaign(Path folder) {
        return Files.isRegularFile(folder.resolve(FILE));
    }

    public CampaignManifest complete(boolean done) {
        return new CampaignManifest(config, version, shard, done);
    }

    List<String> lines() {
        CampaignConfig c = config;
        Map<String, String> m = new TreeMap<>();
        m.put("preset", c.name());
        m.put("sitcov_version", version);
        m.put("master_seed", Long.toString(c.masterSeed()));
        if (c.onRequirements()) {
            m.put("requirements", Requirement.format(c.requirements()));
        } else if (c.onlySeeded()) {
            m.put("faults", FaultSet.format(Set.copyOf(Variant.faultsOf(c.variants()))));
        } else {
            m.put("variants", VariantList.format(c.variants()));
        }
        if (!shard.isWhole()) {
            m.put("shard", shard.toString());
        }
        m.put("drivers", String.join(",", c.drivers()));
        m.put("trials", Integer.toString(c.trials()));
        m.put("tick_budget", Long.toString(c.tickBudget()));
        m.put("candidate_limit", Integer.toString(c.candidateLimit()));
        m.put("faulty_runs", c.faultyRuns().key());
        m.put("controller", c.controller());
        m.put("grid", ResultsFolder.GRID);
        m.put("grid_sha256", Manifest.sha256(c.grid().format()));
        m.put("complete", Boolean.toString(complete));
        List<String> rows = new ArrayList<>();
        rows.add(HEADER);
        m.forEach((k, v) -> rows.add(k + "=" + v));
        return rows;
    }

    public void write(Path folder) throws IOException {
        OutputFile.writeLines(folder.resolve(ResultsFolder.GRID), Arrays.asList(config.grid().format().split("\n")));
        OutputFile.writeLines(folder.resolve(FILE), lines());
    }

    /** @throws IllegalArgumentException naming the file and what is missing or wrong */
    public static CampaignManifest read(Path folder) throws IOException {
        Path file = folder.resolve(FILE);
        Properties p = new Properties();
        try {
            p.load(new StringReader(Files.readString(file, StandardCharsets.UTF_8)));
        } catch (NoSuchFileException e) {
            throw new IllegalArgumentException(folder + " is not a campaign's results folder: it has no " + FILE);
        }
        try {
            GridDefinition grid = GridDefinition.read(folder.resolve(ResultsFolder.GRID));
            if (!Manifest.sha256(grid.format()).equals(required(p, "grid_sha256"))) {
                throw new IllegalArgumentException(ResultsFolder.GRID + " does not match grid_sha256: the grid was edited");
            }
            List<CampaignTarget> targets = p.containsKey("requirements")
                    ? CampaignConfig.ofRequirements(Stream.of(p.getProperty("requirements").split(","))
                            .map(Requirement::ofKey).toList())
                    : CampaignConfig.ofVariants(p.containsKey("variants") ? VariantList.parse(p.getProperty("variants"))
                            : ExperimentConfig.seeded(FaultSet.parse(required(p, "faults"))));
            CampaignConfig c = new CampaignConfig(required(p, "preset"), Long.parseLong(required(p, "master_seed")),
                    targets, List.of(required(p, "drivers").split(",")),
                    Integer.parseInt(required(p, "trials")), Long.parseLong(required(p, "tick_budget")),
                    Integer.parseInt(required(p, "candidate_limit")), grid, FaultyRuns.ofKey(required(p, "faulty_runs")),
                    required(p, "controller"));
            Shard shard = p.containsKey("shard") ? Shard.parse(p.getProperty("shard")) : Shard.WHOLE;
            return new CampaignManifest(c, required(p, "sitcov_version"), shard,
                    Boolean.parseBoolean(required(p, "complete")));
        } catch (NoSuchFileException e) {
            throw new IllegalArgumentException(folder + " lacks " + e.getFile() + "; it is not a whole campaign folder");
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
}
