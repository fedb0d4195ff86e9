package sitcov.report;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.stream.Stream;
import sitcov.analysis.Summary;
import sitcov.control.ControllerFactory;
import sitcov.experiment.DriverSpend;
import sitcov.experiment.Journal;
import sitcov.experiment.Shard;
import sitcov.results.FolderLock;
import sitcov.results.JournalFiles;
import sitcov.results.Manifest;
import sitcov.results.ResultsFolder;

/**
 * Combines the folders of shards 1/N … N/N of one experiment into the folder the unsharded run
 * would have written. Refuses folders of different experiments (preset, seeds, drivers, budget,
 * faults, grid, sitcov version), incomplete ones, and a set of shards with one missing or twice.
 */
public final class ShardMerger {
    private ShardMerger() {
    }

    /**
     * @throws IllegalArgumentException naming the folder and what is wrong with it, or when {@code out} holds files
     * @throws IllegalStateException when another run or merge is writing into {@code out}
     */
    public static Summary merge(List<Path> shards, Path out, Map<String, String> execution, ControllerFactory builtin)
            throws IOException {
        if (shards.isEmpty()) {
            throw new IllegalArgumentException("name the shard folders to merge");
        }
        List<Manifest> manifests = new ArrayList<>();
        for (Path shard : shards) {
            manifests.add(Manifest.read(shard));
        }
        Manifest first = manifests.get(0);
        Path[] byK = shardsByK(shards, manifests);
        int n = first.shard().n();
        boolean resumed = manifests.stream().anyMatch(Manifest::resumed);
        Journal journal = joined(byK, shards, manifests);
        // a shard written before checks leaves the merged folder without them: its rows were never checked
        boolean checked = manifests.stream().allMatch(Manifest::checked);
        // recordings=all only where every shard kept every run: another's passing runs are not at hand
        Manifest merged = new Manifest(first.config(), first.version(), sitcov.experiment.Shard.WHOLE, false, resumed, checked,
                manifests.stream().allMatch(Manifest::recordsAll));
        Files.createDirectories(out);
        try (FolderLock lock = FolderLock.claim(out)) {
            requireEmpty(out);
            merged.write(out);
            for (int k = 1; k <= n; k++) {
                copySituations(byK[k], out);
            }
            Map<String, String> facts = new TreeMap<>(execution);
            facts.put("merged_shards", String.join(" ", Stream.of(byK).skip(1).map(Path::toString).toList()));
            return ResultsFinisher.finish(out, merged, journal, facts, builtin);
        }
    }

    /**
     * Refuses a merge into a folder that holds anything but its lock. Called under the lock: of two merges into one
     * folder, the later finds the earlier's files.
     */
    static void requireEmpty(Path out) throws IOException {
        try (Stream<Path> files = Files.list(out)) {
            if (files.anyMatch(f -> !f.getFileName().toString().equals(ResultsFolder.LOCK))) {
                throw new IllegalArgumentException(out + " holds files already; merge into a new or empty folder");
            }
        }
    }

    /**
     * The shard folders by their K, each checked to be a complete shard of the same experiment and split.
     *
     * @throws IllegalArgumentException naming the folder that does not fit, or the shards missing
     */
    private static Path[] shardsByK(List<Path> shards, List<Manifest> manifests) {
        Manifest first = manifests.get(0);
        int n = first.shard().n();
        Path[] byK = new Path[n + 1];
        for (int i = 0; i < shards.size(); i++) {
            Manifest m = manifests.get(i);
            Path folder = shards.get(i);
            if (!m.identity().equals(first.identity())) {
                throw new IllegalArgumentException(folder + " is not a shard of the same experiment as " + shards.get(0) + ": "
                        + difference(first.identity(), m.identity()));
            }
            if (m.shard().isWhole()) {
                throw new IllegalArgumentException(folder + " holds a whole run, not a shard; merge the folders of run --shard K/N");
            }
            if (m.shard().n() != n) {
                throw new IllegalArgumentException(folder + " is shard " + m.shard() + " but " + shards.get(0) + " is shard "
                        + first.shard() + ": merge shards of one split");
            }
            if (!m.complete()) {
                throw new IllegalArgumentException(folder + " (shard " + m.shard() + ") is not complete; finish it with"
                        + " run --resume " + folder);
            }
            if (byK[m.shard().k()] != null) {
                throw new IllegalArgumentException("shard " + m.shard() + " is given twice: " + byK[m.shard().k()] + " and " + folder);
            }
            byK[m.shard().k()] = folder;
        }
        List<String> missing = new ArrayList<>();
        for (int k = 1; k <= n; k++) {
            if (byK[k] == null) {
                missing.add(k + "/" + n);
            }
        }
        if (!missing.isEmpty()) {
            throw new IllegalArgumentException("shard" + (missing.size() > 1 ? "s " : " ") + String.join(", ", missing)
                    + " missing: merge needs all " + n + " shards");
        }
        return byK;
    }

    /** The shards' journals joined in shard order, each map in its order, every row checked to be its shard's share. */
    private static Journal joined(Path[] byK, List<Path> shards, List<Manifest> manifests) throws IOException {
        int n = byK.length - 1;
        Journal journal = Journal.empty();
        for (int k = 1; k <= n; k++) {
            Journal part = JournalFiles.read(byK[k], manifests.get(shards.indexOf(byK[k])));
            for (Journal.Entry e : part.entries().stream()
                    .sorted(java.util.Comparator.comparingInt((Journal.Entry x) -> x.run().mapIndex())).toList()) {
                checkShare(byK[k], k, n, e.run().replication());
                journal.add(e);
            }
            for (Journal.Finished f : part.finished()) {
                DriverSpend s = f.spend();
                checkShare(byK[k], k, n, s.replication());
                journal.add(f);
            }
        }
        return journal;
    }

    private static void checkShare(Path folder, int k, int n, int replication) {
        if (replication % n != k - 1) {
            throw new IllegalArgumentException(folder + " (shard " + k + "/" + n + ") holds replication " + replication
                    + ", which belongs to shard " + (replication % n + 1) + "/" + n);
        }
    }

    private static String difference(Map<String, String> a, Map<String, String> b) {
        List<String> diffs = new ArrayList<>();
        for (String key : new TreeMap<>(a).keySet()) {
            if (!a.get(key).equals(b.getOrDefault(key, ""))) {
                diffs.add(key + " " + a.get(key) + " vs " + b.getOrDefault(key, "(none)"));
            }
        }
        for (String key : b.keySet()) {
            if (!a.containsKey(key)) {
                diffs.add(key + " (none) vs " + b.get(key));
            }
        }
        return String.join("; ", diffs);
    }

    private static void copySituations(Path shard, Path out) throws IOException {
        copy(shard, out, ResultsFolder.SITUATIONS, ".situation");
        // a shard's recordings are of its own replications: the union is the unsharded run's
        copy(shard, out, ResultsFolder.RECORDINGS, sitcov.recording.RecordingFile.SUFFIX);
    }

    private static void copy(Path shard, Path out, String folder, String suffix) throws IOException {
        Path from = shard.resolve(folder);
        if (!Files.isDirectory(from)) {
            return;
        }
        Path to = out.resolve(folder);
        Files.createDirectories(to);
        try (Stream<Path> files = Files.list(from)) {
            // its files only: not the temporary files a killed shard left
            for (Path f : files.filter(f -> f.getFileName().toString().endsWith(suffix)
                    && !f.getFileName().toString().startsWith(".")).toList()) {
                Files.copy(f, to.resolve(f.getFileName()), StandardCopyOption.REPLACE_EXISTING);
            }
        }
    }
}
