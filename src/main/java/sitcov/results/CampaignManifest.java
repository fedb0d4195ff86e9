package sitcov.results;

import java.io.IOException;
import java.io.StringReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Properties;
import java.util.Set;
import java.util.TreeMap;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import sitcov.coverage.GridDefinition;
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
 *
 * <p>Its {@code checks} line guards it as a manifest's does ({@link ManifestChecks}): a target dropped from
 * it by hand would otherwise pass, since the sub-folders left are each checked only against it.
 * {@code checked} is false for a folder written before campaigns were checked: it is read, and
 * written again, without them. A complete whole campaign's manifest also holds {@code trials_sha256}, the digest of
 * the campaign.csv written with it, so a folder that keeps only campaign.csv is reported from the trials sitcov
 * wrote ({@link #verifyTrials}).
 */
public record CampaignManifest(CampaignConfig config, String version, Shard shard, boolean complete, boolean checked,
                               Optional<String> trialsSha256) {
    static final String TRIALS_SHA256 = "trials_sha256";

    public static final String FILE = ResultsFolder.CAMPAIGN_MANIFEST;
    private static final String HEADER = "# sitcov campaign manifest";
    /** The sub-folders a campaign writes: one a target ({@link CampaignTarget#folder}). */
    private static final Pattern SUB_FOLDER = Pattern.compile("(fault|variant)-\\d+|requirement-[a-z]+");

    /** The manifest of a whole campaign, with checks, as every campaign is written now. */
    public CampaignManifest(CampaignConfig config, String version, boolean complete) {
        this(config, version, Shard.WHOLE, complete, true, Optional.empty());
    }

    /** The manifest of one shard of a campaign, with checks. */
    public CampaignManifest(CampaignConfig config, String version, Shard shard, boolean complete) {
        this(config, version, shard, complete, true, Optional.empty());
    }

    /** Whether {@code other} is a folder of the same campaign, whatever shard each holds and whether it is complete. */
    public boolean sameCampaign(CampaignManifest other) {
        return whole().complete(false).lines().equals(other.whole().complete(false).lines());
    }

    /** The same campaign, whole and checked: what merging its shards makes. */
    public CampaignManifest whole() {
        return new CampaignManifest(config, version, Shard.WHOLE, complete, true, trialsSha256);
    }

    /** Whether {@code folder} holds a campaign (rather than one experiment). */
    public static boolean isCampaign(Path folder) {
        return Files.isRegularFile(folder.resolve(FILE));
    }

    /** Marked complete or not; a campaign not complete has no trials to digest. */
    public CampaignManifest complete(boolean done) {
        return new CampaignManifest(config, version, shard, done, checked, done ? trialsSha256 : Optional.empty());
    }

    /** Complete, with the digest of the campaign.csv just written beside it, whose rows are {@code trials}. */
    public CampaignManifest completeWith(List<String> trials) {
        return new CampaignManifest(config, version, shard, true, checked,
                Optional.of(Manifest.sha256(String.join("\n", trials) + "\n")));
    }

    /**
     * Checks that campaign.csv, whose content is {@code text}, is the one this manifest was written with
     * ({@code trials_sha256} is the file's SHA-256, as {@code sha256sum campaign.csv} gives it).
     *
     * @return false where the manifest, written before it held the digest, cannot tell
     * @throws IllegalArgumentException when campaign.csv was changed after sitcov wrote it
     */
    public boolean verifyTrials(Path folder, String text) {
        if (trialsSha256.isEmpty()) {
            return false;
        }
        if (!trialsSha256.get().equals(Manifest.sha256(text))) {
            throw new IllegalArgumentException(folder.resolve(ResultsFolder.CAMPAIGN_TRIALS) + " was changed after sitcov"
                    + " wrote it (it does not match " + TRIALS_SHA256 + " in " + FILE + "); put back the file the campaign"
                    + " wrote, or run the campaign again into a new folder: " + Manifest.again(folder));
        }
        return true;
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
        trialsSha256.ifPresent(t -> m.put(TRIALS_SHA256, t));
        return ManifestChecks.lines(HEADER, m, checked, complete);
    }

    /** What to say of a campaign written before its manifest was checked, which is read as it is. */
    public static String uncheckedWarning(Path folder) {
        return "warning: " + folder.resolve(FILE) + " was written before sitcov checked it, so a hand edit to it cannot be"
                + " detected (its sub-folders' can); for a campaign that is checked, " + Manifest.again(folder);
    }

    public void write(Path folder) throws IOException {
        OutputFile.writeLines(folder.resolve(ResultsFolder.GRID), Arrays.asList(config.grid().format().split("\n")));
        OutputFile.writeLines(folder.resolve(FILE), lines());
    }

    /** @throws IllegalArgumentException naming the file and what is missing or wrong */
    public static CampaignManifest read(Path folder) throws IOException {
        Path file = folder.resolve(FILE);
        Properties p = new Properties();
        String text;
        try {
            text = Files.readString(file, StandardCharsets.UTF_8);
            p.load(new StringReader(text));
        } catch (NoSuchFileException e) {
            throw new IllegalArgumentException(folder + " is not a campaign's results folder: it has no " + FILE);
        }
        String fix = "put " + FILE + " back as it was, or run the campaign again into a new folder";
        if (p.containsKey(ManifestChecks.CHECKS)) {
            ManifestChecks.verify(text, file, fix);
        }
        CampaignConfig c;
        Shard shard;
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
            c = new CampaignConfig(required(p, "preset"), Long.parseLong(required(p, "master_seed")),
                    targets, List.of(required(p, "drivers").split(",")),
                    Integer.parseInt(required(p, "trials")), Long.parseLong(required(p, "tick_budget")),
                    Integer.parseInt(required(p, "candidate_limit")), grid, FaultyRuns.ofKey(required(p, "faulty_runs")),
                    required(p, "controller"));
            shard = p.containsKey("shard") ? Shard.parse(p.getProperty("shard")) : Shard.WHOLE;
        } catch (NoSuchFileException e) {
            throw new IllegalArgumentException(folder + " lacks " + e.getFile() + "; it is not a whole campaign folder");
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException(file + ": " + e.getMessage(), e);
        }
        unlisted(folder, c).ifPresent(sub -> {
            throw new IllegalArgumentException(file + " lists no target of " + folder.resolve(sub) + ", a sub-folder the"
                    + " campaign wrote: the file was changed after sitcov wrote it; " + fix);
        });
        return new CampaignManifest(c, required(p, "sitcov_version"), shard, Boolean.parseBoolean(required(p, "complete")),
                p.containsKey(ManifestChecks.CHECKS), Optional.ofNullable(p.getProperty(TRIALS_SHA256)).map(String::strip));
    }

    /** A sub-folder of the campaign's kind that none of its targets names: what a target dropped by hand leaves. */
    private static Optional<String> unlisted(Path folder, CampaignConfig c) throws IOException {
        Set<String> listed = c.targets().stream().map(CampaignTarget::folder).collect(Collectors.toSet());
        try (Stream<Path> entries = Files.list(folder)) {
            return entries.filter(Files::isDirectory).map(d -> d.getFileName().toString())
                    .filter(n -> SUB_FOLDER.matcher(n).matches() && !listed.contains(n)).sorted().findFirst();
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
