package sitcov.estimate;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.TreeSet;
import sitcov.results.Manifest;
import sitcov.results.ManifestChecks;

/**
 * An estimate's results folder: manifest.properties, samples.csv, proposals.csv, estimate.csv and
 * estimate.txt. The estimates are always made from the rows of samples.csv as written, so a shard's
 * folders merged ({@link #merge}) give the same bytes as the unsharded run.
 */
public final class EstimateFolder {
    public static final String SAMPLES = "samples.csv";
    public static final String PROPOSALS = "proposals.csv";
    public static final String ESTIMATES = "estimate.csv";
    public static final String TEXT = "estimate.txt";

    private EstimateFolder() {
    }

    /** Whether {@code folder} holds an estimate (its manifest says protocol=estimate). */
    public static boolean isEstimate(Path folder) {
        try {
            Path m = folder.resolve(EstimateManifest.FILE);
            return Files.isRegularFile(m) && Files.readAllLines(m, StandardCharsets.UTF_8).contains("protocol=" + EstimateManifest.PROTOCOL);
        } catch (IOException e) {
            return false;
        }
    }

    /**
     * Writes the replications run, in replication order, and their estimates; returns the report. {@code attest}:
     * the manifest keeps the digests of the samples and proposals (false for rows read from a folder that kept none).
     */
    public static EstimateReport write(Path folder, EstimateConfig config, String version, int shardK, int shardN,
                                       List<String> sampleRows, List<String> proposalRows, boolean attest) throws IOException {
        Files.createDirectories(folder);
        String samplesText = text(withHeader(SampleTable.header(), sampleRows));
        String proposalsText = text(withHeader(ProposalTable.header(), proposalRows));
        write(folder.resolve(SAMPLES), samplesText);
        write(folder.resolve(PROPOSALS), proposalsText);
        List<Sample> samples = sampleRows.stream().map(SampleTable::parse).toList();
        EstimateReport report = new EstimateReport(config, samples);
        writeLines(folder.resolve(ESTIMATES), withHeader(EstimateReport.csvHeader(), report.csvRows()));
        writeLines(folder.resolve(TEXT), report.text());
        // the manifest last: complete=true only once every other file is whole
        writeLines(folder.resolve(EstimateManifest.FILE), EstimateManifest.lines(config, version, shardK, shardN, true,
                attest ? Optional.of(List.of(Manifest.sha256(samplesText), Manifest.sha256(proposalsText))) : Optional.empty()));
        return report;
    }

    /** Whether {@code folder}'s manifest keeps the digests of its samples and proposals. */
    public static boolean attested(Path folder) throws IOException {
        return EstimateManifest.parse(Files.readAllLines(folder.resolve(EstimateManifest.FILE)))
                .containsKey(EstimateManifest.SAMPLES_SHA256);
    }

    /**
     * The shard folders 1/N … N/N of one estimate merged into {@code target}.
     *
     * @throws IllegalArgumentException naming what does not fit: a folder that is no estimate, an
     *                                  incomplete one, another plan or version, a shard missing or twice
     */
    public static EstimateReport merge(List<Path> shards, Path target) throws IOException {
        Map<String, String> first = null;
        TreeSet<Integer> seen = new TreeSet<>();
        int n = -1;
        boolean attest = true;
        List<String> samples = new ArrayList<>();
        List<String> proposals = new ArrayList<>();
        for (Path shard : shards) {
            if (!isEstimate(shard)) {
                throw new IllegalArgumentException(shard + " holds no estimate (no manifest.properties with protocol=estimate)");
            }
            Path file = shard.resolve(EstimateManifest.FILE);
            String text = Files.readString(file, StandardCharsets.UTF_8);
            Map<String, String> m = EstimateManifest.parse(List.of(text.split("\n")));
            if (m.containsKey(ManifestChecks.CHECKS)) {
                ManifestChecks.verify(text, file, "put the file back as sitcov wrote it, or run the estimate again into a"
                        + " new folder");
            }
            if (!"true".equals(m.get("complete"))) {
                throw new IllegalArgumentException(shard + " is not complete; run that shard to its end first");
            }
            String[] kn = m.getOrDefault("shard", "").split("/");
            int k = Integer.parseInt(kn[0]);
            int thisN = Integer.parseInt(kn[1]);
            if (first == null) {
                first = m;
                n = thisN;
            } else if (!samePlan(first, m)) {
                throw new IllegalArgumentException(shard + " is a shard of another estimate (its manifest differs from "
                        + shards.get(0) + "'s beyond shard=)");
            }
            if (thisN != n || !seen.add(k)) {
                throw new IllegalArgumentException(shard + " is shard " + k + "/" + thisN + ", " + (thisN != n
                        ? "not one of " + n : "named twice"));
            }
            attest &= verified(shard, m, SAMPLES, EstimateManifest.SAMPLES_SHA256)
                    & verified(shard, m, PROPOSALS, EstimateManifest.PROPOSALS_SHA256);
            samples.addAll(body(shard.resolve(SAMPLES)));
            proposals.addAll(body(shard.resolve(PROPOSALS)));
        }
        if (seen.size() != n) {
            throw new IllegalArgumentException("shards " + missing(seen, n) + " of " + n + " are missing");
        }
        // a stable sort by replication: each replication's rows keep their stage order, as one run writes them
        Comparator<String> byReplication = Comparator.comparingInt(l -> Integer.parseInt(l.substring(0, l.indexOf(','))));
        samples.sort(byReplication);
        proposals.sort(byReplication);
        return write(target, EstimateManifest.config(first), first.get("version"), 1, 1, samples, proposals, attest);
    }

    /**
     * Whether {@code file} of {@code shard} is the one its manifest's digest names; false where the manifest keeps none.
     *
     * @throws IllegalArgumentException when the file was changed after sitcov wrote it
     */
    private static boolean verified(Path shard, Map<String, String> manifest, String file, String key) throws IOException {
        String digest = manifest.get(key);
        if (digest == null) {
            return false;
        }
        if (!digest.equals(Manifest.sha256(Files.readString(shard.resolve(file), StandardCharsets.UTF_8)))) {
            throw new IllegalArgumentException(shard.resolve(file) + " was changed after sitcov wrote it (it does not match "
                    + key + " in " + EstimateManifest.FILE + "); put back the file the estimate wrote, or run the estimate"
                    + " again into a new folder");
        }
        return true;
    }

    private static boolean samePlan(Map<String, String> a, Map<String, String> b) {
        Map<String, String> x = new java.util.HashMap<>(a);
        Map<String, String> y = new java.util.HashMap<>(b);
        for (String perShard : List.of("shard", EstimateManifest.SAMPLES_SHA256, EstimateManifest.PROPOSALS_SHA256,
                ManifestChecks.CHECKS)) {
            x.remove(perShard);
            y.remove(perShard);
        }
        return x.equals(y);
    }

    private static String missing(TreeSet<Integer> seen, int n) {
        List<String> m = new ArrayList<>();
        for (int k = 1; k <= n; k++) {
            if (!seen.contains(k)) {
                m.add(k + "/" + n);
            }
        }
        return String.join(", ", m);
    }

    private static List<String> body(Path file) throws IOException {
        List<String> lines = Files.readAllLines(file, StandardCharsets.UTF_8);
        return lines.isEmpty() ? List.of() : new ArrayList<>(lines.subList(1, lines.size()));
    }

    private static List<String> withHeader(String header, List<String> rows) {
        List<String> all = new ArrayList<>();
        all.add(header);
        all.addAll(rows);
        return all;
    }

    private static void writeLines(Path file, List<String> lines) throws IOException {
        write(file, text(lines));
    }

    private static String text(List<String> lines) {
        return String.join("\n", lines) + "\n";
    }

    /** Written whole: into a temporary file beside it, then moved into place. */
    private static void write(Path file, String text) throws IOException {
        Path tmp = file.resolveSibling("." + file.getFileName() + ".tmp");
        Files.write(tmp, text.getBytes(StandardCharsets.UTF_8));
        Files.move(tmp, file, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
    }
}
